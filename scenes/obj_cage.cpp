#include "scenes/obj_cage.h"

#include "scenes/input_error.h"
#include "scenes/input_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>

namespace facet::scene {

namespace {

std::vector<std::string_view> splitWhitespace(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

// A token of the file in an error, quoted only when it could be OBJ's: short
// and of letters, digits and `_ . + - /`. Anything else (a line of a file
// that is not OBJ at all, /etc/shadow's say) is described, never repeated.
// Built by appending: GCC 12 warns (-Wrestrict, a false positive) on
// "'" + std::string(...).
std::string inQuotes(std::string_view text) {
  constexpr std::size_t kLongestQuoted = 32;
  const bool objLike = text.size() <= kLongestQuoted && std::all_of(text.begin(), text.end(), [](char c) {
                         return std::isalnum(static_cast<unsigned char>(c)) || (c != '\0' && std::strchr("_.+-/", c));
                       });
  if (!objLike) return "a token of " + std::to_string(text.size()) + " characters that OBJ does not write (not quoted)";
  std::string result(1, '\'');
  result.append(text);
  result.push_back('\'');
  return result;
}

// Parses the whole token or nothing; from_chars rejects a leading '+', OBJ
// writers sometimes emit one.
template <typename T>
bool parseNumber(std::string_view token, T& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end;
}

// Everything a rule needs to blame the right line.
class ObjReader {
 public:
  explicit ObjReader(const std::string& source) { cage_.source = source; }

  void readLine(std::string_view text, int lineNumber) {
    line_ = lineNumber;
    if (size_t hash = text.find('#'); hash != std::string_view::npos) text = text.substr(0, hash);
    std::vector<std::string_view> tokens = splitWhitespace(text);
    if (tokens.empty()) return;
    std::string_view keyword = tokens.front();
    if (keyword == "v")
      readVertex(tokens);
    else if (keyword == "vt")
      readTexcoord(tokens);
    else if (keyword == "vn")
      readNormal(tokens);
    else if (keyword == "f")
      readFace(tokens);
    else if (keyword == "t")
      readTag(tokens);
    else if (keyword == "s" || keyword == "g" || keyword == "o" || keyword == "usemtl" || keyword == "mtllib" ||
             keyword == "l" || keyword == "p")
      return;
    else
      fail("unknown statement", inQuotes(keyword) + " is not an OBJ statement this reader knows");
  }

  ControlCage finish(int lastLine) {
    line_ = lastLine;
    if (cage_.faceVertexCounts.empty()) fail("empty cage", "the file defines no faces");
    checkFaceReferences();
    checkTexcoordCorners();
    checkTagReferences();
    applyPropagateCorners();
    return std::move(cage_);
  }

 private:
  [[noreturn]] void fail(const std::string& rule, const std::string& detail) const {
    throw InputError(cage_.source, line_, rule, detail);
  }
  [[noreturn]] void failAt(int line, const std::string& rule, const std::string& detail) const {
    throw InputError(cage_.source, line, rule, detail);
  }

  double finiteNumber(std::string_view token, const char* what) const {
    double value = 0.0;
    if (!parseNumber(token, value))
      fail("malformed number", std::string(what) + " " + inQuotes(token) + " is not a number");
    if (!std::isfinite(value))
      fail("non-finite value", std::string(what) + " " + inQuotes(token) + " is NaN or infinite");
    return value;
  }

  int integer(std::string_view token, const char* what) const {
    int value = 0;
    if (!parseNumber(token, value))
      fail("malformed integer", std::string(what) + " " + inQuotes(token) + " is not an integer");
    return value;
  }

  void readVertex(const std::vector<std::string_view>& tokens) {
    if (tokens.size() != 4 && tokens.size() != 5) fail("malformed vertex", "'v' needs x y z [w]");
    glm::dvec3 p;
    for (int axis = 0; axis < 3; ++axis) p[axis] = finiteNumber(tokens[axis + 1], "coordinate");
    if (tokens.size() == 5) finiteNumber(tokens[4], "weight");
    cage_.positions.push_back(p);
  }

  // The attribute's numbers, each finite, minValues to maxValues of them.
  std::vector<double> readAttribute(const std::vector<std::string_view>& tokens, size_t minValues, size_t maxValues,
                                    const char* what) const {
    size_t values = tokens.size() - 1;
    if (values < minValues || values > maxValues)
      fail("malformed " + std::string(what), "expected " + std::to_string(minValues) + " to " +
                                                 std::to_string(maxValues) + " numbers, found " +
                                                 std::to_string(values));
    std::vector<double> numbers;
    for (size_t i = 1; i < tokens.size(); ++i) numbers.push_back(finiteNumber(tokens[i], what));
    return numbers;
  }

  // u v [w]: w (a 3D texture's depth) is ignored.
  void readTexcoord(const std::vector<std::string_view>& tokens) {
    const std::vector<double> uvw = readAttribute(tokens, 2, 3, "texture coordinate");
    cage_.texcoords.push_back({uvw[0], uvw[1]});
  }

  void readNormal(const std::vector<std::string_view>& tokens) {
    readAttribute(tokens, 3, 3, "normal");
    ++normalCount_;
  }

  // OBJ indices are 1-based; negative ones count back from the last element
  // defined so far. Positive ones are checked once the whole file is read,
  // because some writers put faces before the vertices they use.
  int resolveIndex(std::string_view token, int definedSoFar, const char* what) const {
    int index = integer(token, what);
    if (index == 0) fail("index out of range", std::string(what) + " index 0 is invalid (OBJ indices start at 1)");
    if (index > 0) return index - 1;
    int resolved = definedSoFar + index;
    if (resolved < 0)
      fail("index out of range",
           std::string(what) + " index " + std::to_string(index) + " reaches before the first " + what);
    return resolved;
  }

  void readFace(const std::vector<std::string_view>& tokens) {
    int corners = static_cast<int>(tokens.size()) - 1;
    if (corners < 3)
      fail("degenerate face", "a face needs at least 3 vertices, this one has " + std::to_string(corners));
    for (int c = 0; c < corners; ++c) {
      std::string_view corner = tokens[c + 1];
      std::string_view parts[3];
      int partCount = 0;
      size_t start = 0;
      while (true) {
        size_t slash = corner.find('/', start);
        if (partCount == 3) fail("malformed face", "corner '" + std::string(corner) + "' has more than v/vt/vn");
        parts[partCount++] = corner.substr(start, slash == std::string_view::npos ? slash : slash - start);
        if (slash == std::string_view::npos) break;
        start = slash + 1;
      }
      int vertex = resolveIndex(parts[0], cage_.vertexCount(), "vertex");
      int texcoord = -1;
      if (partCount > 1 && !parts[1].empty()) {
        const int defined = int(cage_.texcoords.size());
        texcoord = resolveIndex(parts[1], defined, "texture coordinate");
        requireInRange(texcoord, defined, "texture coordinate");
      }
      cage_.faceVertexTexcoords.push_back(texcoord);
      if (partCount > 2 && !parts[2].empty())
        requireInRange(resolveIndex(parts[2], normalCount_, "normal"), normalCount_, "normal");
      cage_.faceVertexIndices.push_back(vertex);
    }
    cage_.faceVertexCounts.push_back(corners);
    faceLines_.push_back(line_);
  }

  // vt and vn must precede their use: unlike positions they are never
  // written after the faces by the tools we know.
  void requireInRange(int index, int count, const char* what) const {
    if (index >= count)
      fail("index out of range", std::string(what) + " index " + std::to_string(index + 1) + " but only " +
                                     std::to_string(count) + " defined");
  }

  struct Tag {
    std::string name;
    std::vector<int> ints;
    std::vector<float> floats;
    std::vector<std::string> strings;
  };

  Tag parseTag(const std::vector<std::string_view>& tokens) const {
    if (tokens.size() < 3) fail("malformed tag", "expected 't <name> <ints>/<floats>/<strings> <arguments...>'");
    Tag tag{std::string(tokens[1]), {}, {}, {}};
    std::string_view counts = tokens[2];
    size_t slash1 = counts.find('/');
    size_t slash2 = slash1 == std::string_view::npos ? slash1 : counts.find('/', slash1 + 1);
    if (slash2 == std::string_view::npos)
      fail("malformed tag", "argument counts '" + std::string(counts) + "' are not <ints>/<floats>/<strings>");
    int intCount = integer(counts.substr(0, slash1), "tag int count");
    int floatCount = integer(counts.substr(slash1 + 1, slash2 - slash1 - 1), "tag float count");
    int stringCount = integer(counts.substr(slash2 + 1), "tag string count");
    if (intCount < 0 || floatCount < 0 || stringCount < 0) fail("malformed tag", "negative argument count");
    size_t expected = 3 + static_cast<size_t>(intCount) + floatCount + stringCount;
    if (tokens.size() != expected)
      fail("malformed tag", "counts " + std::string(counts) + " announce " + std::to_string(expected - 3) +
                                " arguments, found " + std::to_string(tokens.size() - 3));
    size_t next = 3;
    for (int i = 0; i < intCount; ++i) tag.ints.push_back(integer(tokens[next++], "tag integer"));
    for (int i = 0; i < floatCount; ++i)
      tag.floats.push_back(static_cast<float>(finiteNumber(tokens[next++], "tag value")));
    for (int i = 0; i < stringCount; ++i) tag.strings.emplace_back(tokens[next++]);
    return tag;
  }

  void requireArguments(const Tag& tag, size_t ints, size_t floats, size_t strings) const {
    if (tag.ints.size() != ints || tag.floats.size() != floats || tag.strings.size() != strings)
      fail("malformed tag", inQuotes(tag.name) + " takes " + std::to_string(ints) + "/" + std::to_string(floats) + "/" +
                                std::to_string(strings) + " arguments");
  }

  // One sharpness for all items, or one per item.
  float sharpnessFor(const Tag& tag, size_t item, size_t items) const {
    if (tag.floats.size() != 1 && tag.floats.size() != items)
      fail("malformed tag",
           inQuotes(tag.name) + " needs one sharpness or one per item, found " + std::to_string(tag.floats.size()));
    float sharpness = tag.floats.size() == 1 ? tag.floats[0] : tag.floats[item];
    if (sharpness < 0.0f)
      fail("negative sharpness", inQuotes(tag.name) + " sharpness " + std::to_string(sharpness) + " is below 0");
    return sharpness;
  }

  // The option a tag's one string names, of the two it may name.
  template <typename Option>
  Option namedOption(const Tag& tag, std::pair<std::string_view, Option> first,
                     std::pair<std::string_view, Option> second) const {
    requireArguments(tag, 0, 0, 1);
    for (const auto& [name, option] : {first, second})
      if (tag.strings[0] == name) return option;
    fail("unknown option", tag.name + " " + inQuotes(tag.strings[0]) + " is not " + inQuotes(first.first) + " or " +
                               inQuotes(second.first));
  }

  void readTag(const std::vector<std::string_view>& tokens) {
    Tag tag = parseTag(tokens);
    SubdivisionOptions& options = cage_.options;
    if (tag.name == "crease") {
      if (tag.ints.empty() || tag.ints.size() % 2 != 0) fail("malformed tag", "'crease' needs vertex pairs");
      if (!tag.strings.empty()) fail("malformed tag", "'crease' takes no strings");
      size_t pairs = tag.ints.size() / 2;
      for (size_t i = 0; i < pairs; ++i) {
        cage_.creases.push_back({tag.ints[2 * i], tag.ints[2 * i + 1], sharpnessFor(tag, i, pairs)});
        creaseLines_.push_back(line_);
      }
    } else if (tag.name == "corner") {
      if (tag.ints.empty() || !tag.strings.empty())
        fail("malformed tag", "'corner' needs vertex indices and sharpness");
      for (size_t i = 0; i < tag.ints.size(); ++i) {
        cage_.corners.push_back({tag.ints[i], sharpnessFor(tag, i, tag.ints.size())});
        cornerLines_.push_back(line_);
      }
    } else if (tag.name == "hole") {
      if (tag.ints.empty() || !tag.floats.empty() || !tag.strings.empty())
        fail("malformed tag", "'hole' takes face indices only");
      for (int face : tag.ints) {
        cage_.holes.push_back(face);
        holeLines_.push_back(line_);
      }
    } else if (tag.name == "interpolateboundary") {
      requireArguments(tag, 1, 0, 0);
      static constexpr BoundaryInterpolation kModes[] = {
          BoundaryInterpolation::None, BoundaryInterpolation::EdgeAndCorner, BoundaryInterpolation::EdgeOnly};
      if (tag.ints[0] < 0 || tag.ints[0] > 2)
        fail("unknown option", "interpolateboundary " + std::to_string(tag.ints[0]) + " is not 0, 1 or 2");
      options.boundary = kModes[tag.ints[0]];
    } else if (tag.name == "facevaryinginterpolateboundary") {
      requireArguments(tag, 1, 0, 0);
      if (tag.ints[0] < 0 || tag.ints[0] > 5)
        fail("unknown option", "facevaryinginterpolateboundary " + std::to_string(tag.ints[0]) + " is not in 0..5");
      options.faceVarying = static_cast<FaceVaryingInterpolation>(tag.ints[0]);
    } else if (tag.name == "facevaryingpropagatecorners") {
      requireArguments(tag, 1, 0, 0);
      if (tag.ints[0] != 0 && tag.ints[0] != 1)
        fail("unknown option", "facevaryingpropagatecorners " + std::to_string(tag.ints[0]) + " is not 0 or 1");
      propagateCorners_ = tag.ints[0] == 1;
    } else if (tag.name == "creasemethod") {
      options.creasing =
          namedOption<CreasingMethod>(tag, {"normal", CreasingMethod::Uniform}, {"chaikin", CreasingMethod::Chaikin});
    } else if (tag.name == "smoothtriangles") {
      options.triangles = namedOption<TriangleSubdivision>(tag, {"catmark", TriangleSubdivision::Catmark},
                                                           {"smooth", TriangleSubdivision::Smooth});
    } else {
      fail("unknown tag", inQuotes(tag.name) + " is not a tag OpenSubdiv 3 applies to Catmull-Clark cages");
    }
  }

  void checkFaceReferences() const {
    const int vertexCount = cage_.vertexCount();
    size_t offset = 0;
    for (size_t face = 0; face < cage_.faceVertexCounts.size(); ++face) {
      for (int c = 0; c < cage_.faceVertexCounts[face]; ++c) {
        int vertex = cage_.faceVertexIndices[offset + c];
        if (vertex >= vertexCount)
          failAt(faceLines_[face], "index out of range",
                 "vertex index " + std::to_string(vertex + 1) + " but only " + std::to_string(vertexCount) +
                     " vertices defined");
      }
      offset += cage_.faceVertexCounts[face];
    }
  }

  // A cage has texture coordinates on every face corner or on none.
  void checkTexcoordCorners() {
    std::vector<int>& corners = cage_.faceVertexTexcoords;
    const bool any = std::any_of(corners.begin(), corners.end(), [](int t) { return t >= 0; });
    size_t offset = 0;
    for (size_t face = 0; any && face < cage_.faceVertexCounts.size(); ++face) {
      for (int c = 0; c < cage_.faceVertexCounts[face]; ++c)
        if (corners[offset + c] < 0)
          failAt(faceLines_[face], "missing texture coordinate",
                 "corner " + std::to_string(c + 1) + " has no vt index, but other faces' corners have");
      offset += cage_.faceVertexCounts[face];
    }
    if (!any) corners.clear();
  }

  // Hbr's propagate-corners flag, which OpenSubdiv 3 folds into its rules:
  // under the corners-plus rules it picks CornersPlus2 (1) or CornersPlus1
  // (0); the other rules have no corners to propagate.
  void applyPropagateCorners() {
    FaceVaryingInterpolation& rule = cage_.options.faceVarying;
    if (!propagateCorners_ ||
        (rule != FaceVaryingInterpolation::CornersPlus1 && rule != FaceVaryingInterpolation::CornersPlus2))
      return;
    rule = *propagateCorners_ ? FaceVaryingInterpolation::CornersPlus2 : FaceVaryingInterpolation::CornersPlus1;
  }

  void checkTagReferences() const {
    std::set<std::pair<int, int>> edges;
    size_t offset = 0;
    for (int count : cage_.faceVertexCounts) {
      for (int c = 0; c < count; ++c) {
        int a = cage_.faceVertexIndices[offset + c];
        int b = cage_.faceVertexIndices[offset + (c + 1) % count];
        edges.insert(std::minmax(a, b));
      }
      offset += count;
    }
    for (size_t i = 0; i < cage_.creases.size(); ++i) {
      const CreaseEdge& crease = cage_.creases[i];
      if (!edges.count(std::minmax(crease.v0, crease.v1)))
        failAt(creaseLines_[i], "crease on a non-edge",
               "vertices " + std::to_string(crease.v0) + " and " + std::to_string(crease.v1) +
                   " (0-based) share no face edge");
    }
    for (size_t i = 0; i < cage_.corners.size(); ++i) {
      int vertex = cage_.corners[i].vertex;
      if (vertex < 0 || vertex >= cage_.vertexCount())
        failAt(cornerLines_[i], "index out of range",
               "corner vertex " + std::to_string(vertex) + " (0-based) but only " +
                   std::to_string(cage_.vertexCount()) + " vertices");
    }
    for (size_t i = 0; i < cage_.holes.size(); ++i) {
      int face = cage_.holes[i];
      if (face < 0 || face >= cage_.faceCount())
        failAt(holeLines_[i], "index out of range",
               "hole face " + std::to_string(face) + " (0-based) but only " + std::to_string(cage_.faceCount()) +
                   " faces");
    }
  }

  ControlCage cage_;
  int line_ = 0;
  int normalCount_ = 0;
  std::optional<bool> propagateCorners_;
  std::vector<int> faceLines_, creaseLines_, cornerLines_, holeLines_;
};

}  // namespace

ControlCage parseObjCage(std::string_view text, const std::string& source) {
  ObjReader reader(source);
  int lineNumber = 0;
  // A UTF-8 byte-order mark (editors on Windows write one) is not part of the first line.
  size_t start = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    reader.readLine(line, ++lineNumber);
    start = end + 1;
  }
  return reader.finish(lineNumber);
}

ControlCage loadObjCage(const std::filesystem::path& path) {
  checkInputFile(path, "the control cage");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path.string(), 0, "missing file", "cannot open for reading");
  std::ostringstream contents;
  contents << file.rdbuf();
  return parseObjCage(contents.str(), path.string());
}

}  // namespace facet::scene
