#include "engine/image/exr_file.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <half.h>

#include <initializer_list>
#include <iterator>
#include <stdexcept>

#include "engine/image/cryptomatte.h"

namespace facet {
namespace {

struct Channel {
  const char* layer;
  const char* name;
  Imf::PixelType type;
  char* base;
  std::size_t stride;  // bytes between pixels
};

// Appends one channel per component of `plane`, named in component order.
template <typename Plane>
void addPlane(std::vector<Channel>& table, const char* layer, std::initializer_list<const char*> names,
              Imf::PixelType type, Plane& plane) {
  int component = 0;
  for (const char* name : names)
    table.push_back({layer, name, type, reinterpret_cast<char*>(plane.data()) + component++ * sizeof(float),
                     sizeof(typename Plane::value_type)});
}

// The Image's planes, shared by the writer and the reader.
std::vector<Channel> imageChannels(Image& image) {
  std::vector<Channel> table;
  addPlane(table, "beauty", {"R", "G", "B", "A"}, Imf::FLOAT, image.beauty);
  addPlane(table, "depth", {"Z"}, Imf::FLOAT, image.depth);
  addPlane(table, "position", {"P.X", "P.Y", "P.Z"}, Imf::FLOAT, image.position);
  addPlane(table, "normals", {"Ng.X", "Ng.Y", "Ng.Z"}, Imf::FLOAT, image.geometricNormal);
  addPlane(table, "normals", {"N.X", "N.Y", "N.Z"}, Imf::FLOAT, image.shadingNormal);
  addPlane(table, "ids", {"patchId"}, Imf::UINT, image.patchId);
  addPlane(table, "ids", {"faceId"}, Imf::UINT, image.faceId);
  addPlane(table, "uv", {"uv.U", "uv.V"}, Imf::FLOAT, image.uv);
  addPlane(table, "texcoord", {"st.s", "st.t"}, Imf::FLOAT, image.texcoord);
  return table;
}

// Planes derived on the host from faceId and the scene's names. A
// Cryptomatte pixel holds (id, coverage) of ranks 0 and 1: the centre
// ray's id with coverage 1, and no second rank (docs/outputs.md).
struct IdPlanes {
  std::vector<std::uint32_t> objectId, materialId;
  std::vector<glm::vec4> cryptoObject, cryptoMaterial;
};

std::vector<float> idsOf(const std::vector<std::string>& names) {
  std::vector<float> ids;
  for (const std::string& name : names) ids.push_back(cryptomatteId(name));
  return ids;
}

IdPlanes idPlanes(const Image& image, const ExrNames& names) {
  const std::vector<float> objectHashes = idsOf(names.objects), materialHashes = idsOf(names.materials);
  IdPlanes planes{std::vector<std::uint32_t>(image.pixelCount(), Image::kNoId),
                  std::vector<std::uint32_t>(image.pixelCount(), Image::kNoId),
                  std::vector<glm::vec4>(image.pixelCount(), glm::vec4(0.0f)),
                  std::vector<glm::vec4>(image.pixelCount(), glm::vec4(0.0f))};
  for (std::size_t i = 0; i < image.pixelCount(); ++i) {
    const std::uint32_t object = objectOfFace(names, image.faceId[i]);
    if (object == Image::kNoId) continue;
    const std::uint32_t material = names.materialOf[object];
    planes.objectId[i] = object;
    planes.materialId[i] = material;
    planes.cryptoObject[i] = {objectHashes[object], 1.0f, 0.0f, 0.0f};
    planes.cryptoMaterial[i] = {materialHashes[material], 1.0f, 0.0f, 0.0f};
  }
  return planes;
}

std::vector<Channel> idChannels(IdPlanes& p) {
  std::vector<Channel> table;
  addPlane(table, "ids", {"objectId"}, Imf::UINT, p.objectId);
  addPlane(table, "ids", {"materialId"}, Imf::UINT, p.materialId);
  addPlane(table, "crypto", {"CryptoObject00.R", "CryptoObject00.G", "CryptoObject00.B", "CryptoObject00.A"},
           Imf::FLOAT, p.cryptoObject);
  addPlane(table, "crypto", {"CryptoMaterial00.R", "CryptoMaterial00.G", "CryptoMaterial00.B", "CryptoMaterial00.A"},
           Imf::FLOAT, p.cryptoMaterial);
  return table;
}

// The Cryptomatte specification's header entries of one layer.
void insertCryptomatte(Imf::Header& header, const std::string& layer, const std::vector<std::string>& names) {
  const std::string prefix = "cryptomatte/" + cryptomatteKey(layer) + "/";
  header.insert(prefix + "name", Imf::StringAttribute(layer));
  header.insert(prefix + "hash", Imf::StringAttribute("MurmurHash3_32"));
  header.insert(prefix + "conversion", Imf::StringAttribute("uint32_to_float32"));
  header.insert(prefix + "manifest", Imf::StringAttribute(cryptomatteManifest(names)));
}

Imath::M44f m44f(const RowMatrix& m) {
  float x[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) x[i][j] = float(m[i][j]);
  return Imath::M44f(x);
}

void insertMetadata(Imf::Header& header, const ExrMetadata& metadata, bool crypto) {
  if (metadata.camera) {
    Imf::addWorldToCamera(header, m44f(worldToCamera(*metadata.camera)));
    Imf::addWorldToNDC(header, m44f(worldToNdc(*metadata.camera)));
  }
  const ExrProvenance& made = metadata.provenance;
  if (!made.software.empty()) header.insert("software", Imf::StringAttribute(made.software));
  if (!made.renderSettings.empty()) header.insert(kRenderSettingsAttribute, Imf::StringAttribute(made.renderSettings));
  if (!made.pictureDigest.empty()) header.insert(kPictureDigestAttribute, Imf::StringAttribute(made.pictureDigest));
  // OpenEXR's integer attribute is signed: the seed's 32 bits as they are.
  if (made.estimateSeed) header.insert(kEstimateSeedAttribute, Imf::IntAttribute(int(*made.estimateSeed)));
  if (crypto && metadata.names) {
    insertCryptomatte(header, "CryptoObject", metadata.names->objects);
    insertCryptomatte(header, "CryptoMaterial", metadata.names->materials);
  }
}

// OpenEXR addresses slices by absolute pixel coordinates: the plane's first
// pixel is pixel (x0, y0) of the display window.
Imf::Slice slice(const Channel& c, int x0, int y0, int width) {
  char* origin = c.base - (std::ptrdiff_t(x0) + std::ptrdiff_t(y0) * width) * std::ptrdiff_t(c.stride);
  return Imf::Slice(c.type, origin, c.stride, c.stride * std::size_t(width));
}

}  // namespace

ExrLayers allExrLayers() { return {std::begin(kExrLayers), std::end(kExrLayers)}; }

std::string exrLayerNames() {
  std::string names;
  for (const char* layer : kExrLayers) names += std::string(names.empty() ? "" : ", ") + layer;
  return names;
}

ExrLayers parseExrLayers(const std::string& text, const std::string& flag) {
  if (text == "all") return allExrLayers();
  const ExrLayers known = allExrLayers();
  ExrLayers chosen{"beauty"};
  for (std::size_t begin = 0, end = 0; end != std::string::npos; begin = end + 1) {
    end = text.find(',', begin);
    const std::string name = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    if (!known.count(name))
      throw std::invalid_argument(flag + " '" + text +
                                  "': expected all, or a comma-separated list of: " + exrLayerNames());
    chosen.insert(name);
  }
  return chosen;
}

OutputFile exrFile(const std::filesystem::path& path, const Image& image, const ExrOptions& options) {
  return {path, [path, &image, options](const std::filesystem::path& temporary) {
            const ExrPlacement where = options.placement.value_or(
                ExrPlacement{PixelRect::whole(image.width, image.height), image.width, image.height, {}});
            const PixelRect& data = where.dataWindow;
            Imf::Header header(Imath::Box2i({0, 0}, {where.displayWidth - 1, where.displayHeight - 1}),
                               Imath::Box2i({data.x0, data.y0}, {data.x1 - 1, data.y1 - 1}));
            header.compression() = Imf::ZIP_COMPRESSION;
            if (!where.digest.empty()) header.insert(kSettingsDigestAttribute, Imf::StringAttribute(where.digest));
            const bool crypto = options.layers.count("crypto") > 0,
                       idLayers = crypto || options.layers.count("ids") > 0;
            insertMetadata(header, options.metadata, crypto);

            // The slices only read through these pointers; the table is shared with readExr.
            std::vector<Channel> channels = imageChannels(const_cast<Image&>(image));
            IdPlanes derived;
            if (options.metadata.names && idLayers) {
              derived = idPlanes(image, *options.metadata.names);
              for (const Channel& c : idChannels(derived)) channels.push_back(c);
            }
            std::vector<std::vector<half>> halfPlanes;  // OpenEXR writes half channels from half pixels only
            Imf::FrameBuffer frame;
            for (Channel c : channels) {
              const bool beauty = std::string(c.layer) == "beauty";
              if (!options.layers.count(c.layer) && !beauty) continue;
              if (beauty && options.halfBeauty) {
                std::vector<half>& plane = halfPlanes.emplace_back(image.pixelCount());
                for (std::size_t i = 0; i < plane.size(); ++i)
                  plane[i] = half(*reinterpret_cast<const float*>(c.base + i * c.stride));
                c = {c.layer, c.name, Imf::HALF, reinterpret_cast<char*>(plane.data()), sizeof(half)};
              }
              header.channels().insert(c.name, Imf::Channel(c.type));
              frame.insert(c.name, slice(c, data.x0, data.y0, image.width));
            }
            try {
              Imf::OutputFile file(temporary.c_str(), header);
              file.setFrameBuffer(frame);
              file.writePixels(image.height);
            } catch (const std::exception& e) {
              throw OutputError(path.string() + ": cannot write EXR: " + e.what());
            }
          }};
}

void writeExr(const std::filesystem::path& path, const Image& image, const ExrOptions& options) {
  writeAllOrNothing({exrFile(path, image, options)});
}

ExrProvenance readExrProvenance(const std::filesystem::path& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const auto text = [&](const char* name) {
      const auto* attribute = header.findTypedAttribute<Imf::StringAttribute>(name);
      return attribute ? attribute->value() : std::string();
    };
    ExrProvenance made{text("software"), text(kRenderSettingsAttribute), text(kPictureDigestAttribute), {}};
    if (const auto* seed = header.findTypedAttribute<Imf::IntAttribute>(kEstimateSeedAttribute))
      made.estimateSeed = std::uint32_t(seed->value());
    return made;
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": cannot read EXR: " + e.what());
  }
}

Image readExr(const std::filesystem::path& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    Image image(window.max.x - window.min.x + 1, window.max.y - window.min.y + 1);
    Imf::FrameBuffer frame;
    for (const Channel& c : imageChannels(image))
      if (file.header().channels().findChannel(c.name))
        frame.insert(c.name, slice(c, window.min.x, window.min.y, image.width));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": cannot read EXR: " + e.what());
  }
}

}  // namespace facet
