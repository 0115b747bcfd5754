#include "analysis/reference_cache.h"

#include <facet/version.h>

#include <link.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <system_error>
#include <type_traits>

#include "engine/ibl/cache_bytes.h"
#include "engine/ibl/cache_folder.h"
#include "engine/ibl/prefilter_cache_format.h"
#include "engine/render_record.h"
#include "scenes/light_transport.h"

namespace facet::analysis {
namespace {

namespace fs = std::filesystem;
using ibl::cache_format::fnv1a;
using ibl::cache_format::Reader;
using ibl::cache_format::Writer;

constexpr const char* kFilePrefix = "parity-reference";

// A file's bytes hashed as they are read; none where it cannot be read.
std::optional<std::uint64_t> contentHash(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::uint64_t hash = ibl::cache_format::kFnv1aOffsetBasis;
  std::vector<char> chunk(std::size_t(1) << 20);
  while (in) {
    in.read(chunk.data(), std::streamsize(chunk.size()));
    hash = fnv1a(chunk.data(), std::size_t(in.gcount()), hash);
  }
  if (in.bad()) return std::nullopt;
  return hash;
}

// The shared libraries mapped now, each as a line "path size modified".
std::string mappedLibraries() {
  std::string lines;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* out) {
        struct stat file {};
        if (info->dlpi_name && *info->dlpi_name && stat(info->dlpi_name, &file) == 0)
          *static_cast<std::string*>(out) += std::string("library ") + info->dlpi_name + ' ' +
                                             std::to_string(file.st_size) + ' ' + std::to_string(file.st_mtim.tv_sec) +
                                             '.' + std::to_string(file.st_mtim.tv_nsec) + '\n';
        return 0;
      },
      &lines);
  return lines;
}
// The shared libraries recordProgramAtStart saw; none where it was not called.
std::optional<std::string>& librariesAtStart() {
  static std::optional<std::string> libraries;
  return libraries;
}

// The program's bytes, hashed once, when a key first needs them: the
// command that caches pays for it, the others never do.
std::optional<std::uint64_t> programBytes() {
  static const std::optional<std::uint64_t> hash = contentHash("/proc/self/exe");
  return hash;
}

// Every plane of `image`, in one order for writing and reading.
template <class AnImage, class Visit>
void visitPlanes(AnImage& image, Visit visit) {
  visit(image.beauty);
  visit(image.depth);
  visit(image.position);
  visit(image.geometricNormal);
  visit(image.shadingNormal);
  visit(image.patchId);
  visit(image.faceId);
  visit(image.uv);
  visit(image.texcoord);
}

// A writer killed between its write and its rename leaves its temporary
// file (cache_folder.h); one this old is no live writer's.
constexpr auto kAbandoned = std::chrono::hours(1);

// The reference files least recently used removed until the rest fit
// `budget`; abandoned temporary files removed, live ones left to their writers.
void prune(const fs::path& directory, std::uintmax_t budget) {
  std::vector<std::pair<fs::file_time_type, fs::path>> files;
  std::uintmax_t total = 0;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file(error) || name.rfind(std::string(kFilePrefix) + "-", 0) != 0) continue;
    if (entry.path().extension() != ".bin") {
      if (entry.last_write_time(error) < fs::file_time_type::clock::now() - kAbandoned) fs::remove(entry.path(), error);
      continue;
    }
    total += entry.file_size(error);
    files.emplace_back(entry.last_write_time(error), entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& [time, file] : files) {
    if (total <= budget) break;
    total -= std::min(total, fs::file_size(file, error));
    fs::remove(file, error);
  }
}

}  // namespace

Image CachedReference::render(int i) const {
  if (i == 0) return first;
  Image beautyOnly;
  beautyOnly.width = first.width;
  beautyOnly.height = first.height;
  beautyOnly.beauty = laterBeauty[std::size_t(i - 1)];
  return beautyOnly;
}

void CachedReference::add(const Image& render) {
  if (first.width == 0)
    first = render;
  else
    laterBeauty.push_back(render.beauty);
}

std::vector<char> referencePayload(const CachedReference& reference) {
  Writer w;
  w.putText(reference.device);
  w.put(std::int32_t(reference.first.width));
  w.put(std::int32_t(reference.first.height));
  w.put(std::int32_t(reference.renders()));
  visitPlanes(reference.first, [&](const auto& plane) { w.putArray(plane); });
  for (const std::vector<glm::vec4>& beauty : reference.laterBeauty) w.putArray(beauty);
  return w.data();
}

std::optional<CachedReference> referenceFromPayload(const std::vector<char>& payload, int width, int height,
                                                    int renders) {
  Reader r(payload);
  CachedReference reference;
  reference.device = r.getText();
  reference.first.width = r.get<std::int32_t>();
  reference.first.height = r.get<std::int32_t>();
  if (!r.ok() || reference.first.width != width || reference.first.height != height || r.get<std::int32_t>() != renders)
    return std::nullopt;
  const std::size_t pixels = reference.first.pixelCount();
  visitPlanes(reference.first,
              [&](auto& plane) { plane = r.getArray<typename std::decay_t<decltype(plane)>::value_type>(pixels); });
  for (int i = 1; i < renders; ++i) reference.laterBeauty.push_back(r.getArray<glm::vec4>(pixels));
  if (!r.ok() || !r.atEnd()) return std::nullopt;
  return reference;
}

void recordProgramAtStart() { librariesAtStart() = mappedLibraries(); }

std::string referenceKey(const scene::Scene& scene, const std::vector<fs::path>& inputs, const std::string& shapedBy) {
  const std::optional<std::string>& libraries = librariesAtStart();
  const std::optional<std::uint64_t> program = programBytes();
  if (!libraries || !program) return {};
  std::ostringstream key;
  key << "facet parity reference v1 " FACET_VERSION_STRING "\nprogram " << std::hex << *program << std::dec << '\n'
      << *libraries;
  for (const fs::path& input : inputs) {
    const std::optional<std::uint64_t> hash = contentHash(input);
    if (!hash) return {};
    key << "input " << fs::absolute(input).string() << ' ' << std::hex << *hash << std::dec << '\n';
  }
  key << "shaped by " << shapedBy << '\n'
      << "settings " << renderSettingsText(scene, "parity") << " digest " << settingsDigest(scene, "parity") << '\n'
      << "first seed " << scene::estimateSeed(scene).value_or(0) << '\n';
  return key.str();
}

std::string rendersKey(const std::string& key, int renders) {
  return key.empty() ? key : key + "renders " + std::to_string(renders) + '\n';
}

std::uintmax_t referenceBytes(int width, int height, int renders) {
  const std::uintmax_t pixels = std::uintmax_t(width) * std::uintmax_t(height);
  std::uintmax_t firstBytes = 0;
  Image one;
  visitPlanes(one,
              [&](const auto& plane) { firstBytes += sizeof(typename std::decay_t<decltype(plane)>::value_type); });
  return pixels * (firstBytes + std::uintmax_t(renders - 1) * sizeof(glm::vec4));
}

std::optional<CachedReference> loadReference(const std::string& key, int width, int height, int renders) {
  const std::optional<fs::path> directory = ibl::cacheDirectory();
  if (!directory || key.empty()) return std::nullopt;
  try {
    const fs::path file = ibl::cacheFile(*directory, kFilePrefix, key);
    const auto bytes = ibl::readCacheFile(file);
    if (!bytes) return std::nullopt;
    const auto payload = ibl::cache_format::unseal(*bytes, key);
    if (!payload) return std::nullopt;
    std::optional<CachedReference> reference = referenceFromPayload(*payload, width, height, renders);
    // Marked as used: the budget removes the files least recently used.
    std::error_code error;
    if (reference) fs::last_write_time(file, fs::file_time_type::clock::now(), error);
    return reference;
  } catch (const std::exception&) {  // a file too large to hold: a miss like any other bad file
    return std::nullopt;
  }
}

void storeReference(const std::string& key, const CachedReference& reference, std::uintmax_t budget) {
  const std::optional<fs::path> directory = ibl::cacheDirectory();
  if (!directory || key.empty()) return;
  try {
    const std::vector<char> sealed = ibl::cache_format::seal(key, referencePayload(reference));
    if (sealed.size() > budget) return;
    ibl::writeCacheFileAtomically(ibl::cacheFile(*directory, kFilePrefix, key), sealed);
    prune(*directory, budget);
  } catch (const std::exception&) {  // out of memory for the copy, a folder that vanished: nothing stored
  }
}

}  // namespace facet::analysis
