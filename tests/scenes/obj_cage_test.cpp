#include "scenes/input_error.h"
#include "scenes/obj_cage.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <sys/stat.h>

#include <cctype>
#include <filesystem>
#include <string>

namespace facet::scene {
namespace {

// Expects parseObjCage(text) to throw an InputError at `line` for `rule`.
void expectError(const std::string& text, int line, const std::string& rule) {
  try {
    parseObjCage(text, "test.obj");
    FAIL() << "no error for:\n" << text;
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "test.obj");
    EXPECT_EQ(error.line(), line) << error.what();
    EXPECT_EQ(error.rule(), rule) << error.what();
    const std::string prefix = "test.obj:" + std::to_string(line) + ": " + rule + ": ";
    EXPECT_EQ(std::string(error.what()).rfind(prefix, 0), 0u) << error.what();
  }
}

const std::string kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjCage, ReadsQuadsTrianglesAndNgonsWithEveryCornerSyntax) {
  ControlCage cage = parseObjCage(
      "# comment line\r\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0  1.0\nv 3 0.5 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
      "s off\ng part\no thing\nusemtl steel\n"
      "f 1//1 2//1 3 4//1   # quad, trailing comment\n"
      "f 2 5 6 3 \n"
      "f -3 -1 -2\n"  // negative indices: 5 7 6
      "f 1 2 5 7 6 3 4\n",
      "inline");
  EXPECT_EQ(cage.vertexCount(), 7);
  ASSERT_EQ(cage.faceCount(), 4);
  EXPECT_EQ(cage.faceVertexCounts, (std::vector<int>{4, 4, 3, 7}));
  EXPECT_EQ(std::vector<int>(cage.faceVertexIndices.begin() + 8, cage.faceVertexIndices.begin() + 11),
            (std::vector<int>{4, 6, 5}));
  EXPECT_DOUBLE_EQ(cage.positions[6].x, 3.0);
  EXPECT_DOUBLE_EQ(cage.positions[6].y, 0.5);
}

TEST(ObjCage, ReadsOpenSubdivTags) {
  ControlCage cage = parseObjCage(kQuad +
                                      "v 2 0 0\nv 2 1 0\n"
                                      "f 1 2 3 4\nf 2 5 6 3\n"
                                      "t crease 2/1/0 0 1 2.5\n"
                                      "t crease 4/2/0 1 2 2 3 10 0.5\n"
                                      "t corner 2/1/0 0 3 4.0\n"
                                      "t hole 1/0/0 1\n"
                                      "t interpolateboundary 1/0/0 1\n"
                                      "t facevaryinginterpolateboundary 1/0/0 3\n"
                                      "t creasemethod 0/0/1 chaikin\n"
                                      "t smoothtriangles 0/0/1 smooth\n",
                                  "tags");
  ASSERT_EQ(cage.creases.size(), 3u);
  EXPECT_EQ(cage.creases[0].v0, 0);
  EXPECT_EQ(cage.creases[0].v1, 1);
  EXPECT_FLOAT_EQ(cage.creases[0].sharpness, 2.5f);
  EXPECT_FLOAT_EQ(cage.creases[1].sharpness, 10.0f);
  EXPECT_FLOAT_EQ(cage.creases[2].sharpness, 0.5f);
  ASSERT_EQ(cage.corners.size(), 2u);
  EXPECT_EQ(cage.corners[1].vertex, 3);
  EXPECT_FLOAT_EQ(cage.corners[1].sharpness, 4.0f);
  EXPECT_EQ(cage.holes, (std::vector<int>{1}));
  EXPECT_EQ(cage.options.boundary, BoundaryInterpolation::EdgeAndCorner);
  EXPECT_EQ(cage.options.faceVarying, FaceVaryingInterpolation::CornersPlus2);
  EXPECT_EQ(cage.options.creasing, CreasingMethod::Chaikin);
  EXPECT_EQ(cage.options.triangles, TriangleSubdivision::Smooth);

  EXPECT_EQ(parseObjCage(kQuad + "f 1 2 3 4\n", "defaults").options.boundary, BoundaryInterpolation::EdgeOnly);
  EXPECT_EQ(parseObjCage(kQuad + "f 1 2 3 4\nt interpolateboundary 1/0/0 0\n", "none").options.boundary,
            BoundaryInterpolation::None);
}

TEST(ObjCage, ReadsTextureCoordinatesAsAFaceVaryingChannel) {
  const ControlCage cage = parseObjCage(kQuad +
                                            "v 2 0 0\nv 2 1 0\n"
                                            "vt 0 0\nvt 0.5 0 7\nvt 0.5 1\nvt 0 1\nvt 0.5 0\nvt 1 0\nvn 0 0 1\n"
                                            "f 1/1 2/2 3/3/1 4/4\n"
                                            "f 2/-2 5/-1 6/1 3/3\n",
                                        "uv");
  ASSERT_EQ(cage.texcoords.size(), 6u);
  EXPECT_EQ(cage.texcoords[1], glm::dvec2(0.5, 0.0));  // the third number is ignored
  // Corners of vertex 1 keep their own values: a seam.
  EXPECT_EQ(cage.faceVertexTexcoords, (std::vector<int>{0, 1, 2, 3, 4, 5, 0, 2}));
}

TEST(ObjCage, WithoutTextureCoordinatesTheChannelIsEmpty) {
  const ControlCage cage = parseObjCage(kQuad + "vt 0 0\nf 1 2 3 4\n", "no uv");
  EXPECT_TRUE(cage.faceVertexTexcoords.empty());
}

TEST(ObjCage, PropagateCornersChoosesBetweenTheCornersPlusRules) {
  const std::string quad = kQuad + "f 1 2 3 4\n";
  using FV = FaceVaryingInterpolation;
  const auto rule = [&](const std::string& tags) { return parseObjCage(quad + tags, "tags").options.faceVarying; };
  EXPECT_EQ(rule("t facevaryinginterpolateboundary 1/0/0 2\nt facevaryingpropagatecorners 1/0/0 1\n"),
            FV::CornersPlus2);
  // The order of the tags does not matter.
  EXPECT_EQ(rule("t facevaryingpropagatecorners 1/0/0 1\nt facevaryinginterpolateboundary 1/0/0 2\n"),
            FV::CornersPlus2);
  EXPECT_EQ(rule("t facevaryinginterpolateboundary 1/0/0 3\nt facevaryingpropagatecorners 1/0/0 0\n"),
            FV::CornersPlus1);
  EXPECT_EQ(rule("t facevaryinginterpolateboundary 1/0/0 1\nt facevaryingpropagatecorners 1/0/0 1\n"), FV::CornersOnly);
  EXPECT_EQ(rule("t facevaryingpropagatecorners 1/0/0 1\n"), FV::All);
}

TEST(ObjCage, LoadsEveryTortureCage) {
  int cages = 0;
  for (const auto& entry : std::filesystem::directory_iterator(FACET_CAGE_DIR)) {
    if (entry.path().extension() != ".obj") continue;
    ControlCage cage = loadObjCage(entry.path());
    EXPECT_GT(cage.faceCount(), 0) << entry.path();
    EXPECT_EQ(cage.source, entry.path().string());
    ++cages;
  }
  EXPECT_GE(cages, 9);
}

TEST(ObjCageErrors, MissingFile) {
  try {
    loadObjCage("/nonexistent/facet/cage.obj");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "/nonexistent/facet/cage.obj");
    EXPECT_EQ(error.line(), 0);
    EXPECT_EQ(error.rule(), "cannot open the control cage");
    EXPECT_NE(std::string(error.what()).find("no such file"), std::string::npos);
  }
}

TEST(ObjCage, AByteOrderMarkIsNotPartOfTheFirstLine) {
  const std::string cube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  const ControlCage plain = parseObjCage(cube, "plain.obj");
  const ControlCage marked = parseObjCage("\xEF\xBB\xBF" + cube, "marked.obj");
  EXPECT_EQ(marked.positions, plain.positions);
}

// Only regular files are read: a FIFO would block the read, a device never
// end it, a folder cannot be parsed.
TEST(ObjCageErrors, OnlyRegularFilesAreRead) {
  const std::filesystem::path fifo =
      std::filesystem::temp_directory_path() / ("facet_fifo_" + std::to_string(getpid()));
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const auto messageOf = [](const std::filesystem::path& path) {
    try {
      loadObjCage(path);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("loaded");
  };
  EXPECT_NE(messageOf(fifo).find("it is a FIFO, socket or device"), std::string::npos);
  std::filesystem::remove(fifo);
  EXPECT_NE(messageOf("/dev/zero").find("it is a FIFO, socket or device"), std::string::npos);
  EXPECT_NE(messageOf(std::filesystem::temp_directory_path()).find("it is a folder"), std::string::npos);
}

// Each text with its one error: the line it is reported on and the rule.
struct BadCage {
  std::string text;
  int line;
  std::string rule;
};

const BadCage kBadCages[] = {
    // Malformed lines.
    {kQuad + "v 1 2\nf 1 2 3 4\n", 5, "malformed vertex"},
    {kQuad + "v 1 2 3 4 5\n", 5, "malformed vertex"},
    {kQuad + "v 1 two 3\n", 5, "malformed number"},
    {kQuad + "f 1 2 3 4\nvt 0\n", 6, "malformed texture coordinate"},
    {kQuad + "f 1 2 x 4\n", 5, "malformed integer"},
    {kQuad + "f 1/1/1/1 2 3\n", 5, "malformed face"},
    {kQuad + "f 1 2 3 4\nbogus 1 2\n", 6, "unknown statement"},
    {kQuad + "f 1 2 3 4\nt crease 2/1 0 1 2.0\n", 6, "malformed tag"},
    {kQuad + "f 1 2 3 4\nt crease 2/1/0 0 1\n", 6, "malformed tag"},
    {kQuad + "f 1 2 3 4\nt crease 3/1/0 0 1 2 1.0\n", 6, "malformed tag"},
    {kQuad + "f 1 2 3 4\nt crease 4/3/0 0 1 1 2 1.0 2.0 3.0\n", 6, "malformed tag"},
    {kQuad + "f 1 2 3 4\nt interpolateboundary 1/0/0 7\n", 6, "unknown option"},
    {kQuad + "f 1 2 3 4\nt creasemethod 0/0/1 sharp\n", 6, "unknown option"},
    {kQuad + "f 1 2 3 4\nt facevaryingpropagatecorners 1/0/0 2\n", 6, "unknown option"},
    {kQuad + "f 1 2 3 4\nt facevaryingpropagatecorners 0/0/1 yes\n", 6, "malformed tag"},
    {kQuad + "vt 0 0\nvt 1 0 0 0\n", 6, "malformed texture coordinate"},
    {kQuad + "vt 0 nan\n", 5, "non-finite value"},
    {kQuad + "vt inf 0\n", 5, "non-finite value"},
    {kQuad + "f 1 2 3 4\nt vertexedit 1/0/0 0\n", 6, "unknown tag"},
    {kQuad + "f 1 2 3 4\nt crease 2/1/0 0 1 -1.0\n", 6, "negative sharpness"},
    {"# nothing but a comment\nv 0 0 0\n", 2, "empty cage"},
    // Non-finite coordinates.
    {kQuad + "v nan 0 0\n", 5, "non-finite value"},
    {kQuad + "v 0 inf 0\n", 5, "non-finite value"},
    {kQuad + "v 0 0 -inf\n", 5, "non-finite value"},
    {kQuad + "v 0 0 1e400\n", 5, "malformed number"},  // out of double range
    {kQuad + "f 1 2 3 4\nt crease 2/1/0 0 1 nan\n", 6, "non-finite value"},
    // Indices out of range.
    {kQuad + "f 1 2 3 5\n", 5, "index out of range"},
    {kQuad + "f 1 2 3 0\n", 5, "index out of range"},
    {kQuad + "f -5 -1 -2\n", 5, "index out of range"},
    {kQuad + "vt 0 0\nf 1/2 2/1 3/1\n", 6, "index out of range"},
    {kQuad + "vt 0 0\nf 1/1 2/-2 3/1\n", 6, "index out of range"},
    {kQuad + "vt 0 0\nf 1/0 2/1 3/1\n", 6, "index out of range"},
    // Texture coordinates on some corners only: named on the first face that lacks one.
    {kQuad + "vt 0 0\nf 1/1 2/1 3/1\nf 1/1 3/1 4\n", 7, "missing texture coordinate"},
    {kQuad + "vt 0 0\nf 1 2 3\nf 1/1 3/1 4/1\n", 6, "missing texture coordinate"},
    {kQuad + "vn 0 0 1\nf 1//1 2//2 3//1\n", 6, "index out of range"},
    // Reported on the face's line even when found after the last line.
    {kQuad + "f 1 2 3 4\nf 1 3 9\n# trailer\n", 6, "index out of range"},
    {kQuad + "f 1 2 3 4\nt corner 1/1/0 4 1.0\n", 6, "index out of range"},
    {kQuad + "f 1 2 3 4\nt hole 1/0/0 1\n", 6, "index out of range"},
    {kQuad + "f 1 2 3 4\nt crease 2/1/0 0 2 1.0\n", 6, "crease on a non-edge"},
    // Faces of fewer than three vertices.
    {kQuad + "f 1 2\n", 5, "degenerate face"},
    {kQuad + "f 1 2 3 4\nf 4\n", 6, "degenerate face"},
};

class ObjCageErrorsOnItsLine : public ::testing::TestWithParam<BadCage> {};

TEST_P(ObjCageErrorsOnItsLine, NamesTheLineAndTheRule) {
  expectError(GetParam().text, GetParam().line, GetParam().rule);
}

// The rule and the case's index, as the test's name.
std::string caseName(const ::testing::TestParamInfo<BadCage>& info) {
  std::string name = info.param.rule + "_" + std::to_string(info.index);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(BadCages, ObjCageErrorsOnItsLine, ::testing::ValuesIn(kBadCages), caseName);

// OpenSubdiv subdivides these, so the reader passes them on as written.
// A file that is not OBJ (a password file named as a mesh, say) is refused
// without its contents in the message; OBJ's own tokens are still quoted.
TEST(ObjCageErrors, QuoteOnlyWhatCouldBeObj) {
  const auto messageOf = [](const std::string& text) {
    try {
      parseObjCage(text, "test.obj");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("(no error)");
  };
  const std::string secret = messageOf("root:$y$j9T$aSecretHash:20228:0:99999:7:::\nv 0 0 0\n");
  EXPECT_EQ(secret.find("root"), std::string::npos) << secret;
  EXPECT_EQ(secret.find("Secret"), std::string::npos) << secret;
  EXPECT_NE(secret.find("a token of 42 characters that OBJ does not write (not quoted)"), std::string::npos) << secret;
  const std::string number = messageOf(kQuad + "v 1 " + std::string(40, '7') + "x 3\n");
  EXPECT_NE(number.find("a token of 41 characters"), std::string::npos) << number;
  EXPECT_NE(messageOf(kQuad + "f 1 2 3 4\nbogus 1 2\n").find("'bogus' is not an OBJ statement"), std::string::npos);
  EXPECT_NE(messageOf(kQuad + "v 1 two 3\n").find("'two'"), std::string::npos);
}

TEST(ObjCage, AcceptsWhatOpenSubdivAccepts) {
  const ControlCage repeated = parseObjCage(kQuad + "f 1 2 2 3\nf 1 2 3 -4\n", "repeated");
  EXPECT_EQ(repeated.faceVertexIndices, (std::vector<int>{0, 1, 1, 2, 0, 1, 2, 0}));
  const ControlCage book = parseObjCage(kQuad + "v 0 0 1\nv 0 1 1\nf 1 2 3 4\nf 1 4 6 5\nf 1 5 6 4\n", "book");
  EXPECT_EQ(book.faceCount(), 3);  // edge 1-4 has three faces
  const ControlCage bare = parseObjCage(kQuad + "v 5 5 5\nf 1 2 3 4\n", "bare");
  EXPECT_EQ(bare.vertexCount(), 5);
  for (const char* name : {"nonmanifold_edge", "repeated_vertex", "bare_vertex"})
    EXPECT_GT(loadObjCage(std::string(FACET_TEST_DATA_DIR) + "/" + name + ".obj").faceCount(), 0) << name;
}

}  // namespace
}  // namespace facet::scene
