#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/image/image_io.h"
#include "tests/support/random_image.h"
#include "tests/support/temp_dir.h"

#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

namespace facet {
namespace {

namespace fs = std::filesystem;
using facet::testing::randomImage;

class ImageIo : public facet::testing::TempDirTest {
 protected:
  std::vector<fs::path> files() const { return {fs::directory_iterator(dir_), fs::directory_iterator()}; }
};

TEST_F(ImageIo, ExrRoundTripKeepsEveryChannelBitExact) {
  Image image = randomImage(37, 19);
  writeExr(dir_ / "out.exr", image);
  Image back = readExr(dir_ / "out.exr");
  ASSERT_EQ(back.width, 37);
  ASSERT_EQ(back.height, 19);
  EXPECT_EQ(back.beauty, image.beauty);
  EXPECT_EQ(back.depth, image.depth);  // +inf on misses survives
  EXPECT_EQ(back.position, image.position);
  EXPECT_EQ(back.geometricNormal, image.geometricNormal);
  EXPECT_EQ(back.shadingNormal, image.shadingNormal);
  EXPECT_EQ(back.patchId, image.patchId);
  EXPECT_EQ(back.faceId, image.faceId);
  EXPECT_EQ(back.uv, image.uv);
  EXPECT_EQ(back.texcoord, image.texcoord);
  EXPECT_EQ(files().size(), 1u) << "no temporary file may remain";
}

TEST_F(ImageIo, PngEncodesSrgbAndCoverage) {
  Image image(2, 1);
  image.beauty[0] = {0.5f, 0.0f, 2.0f, 1.0f};  // 0.5 linear is 188 in sRGB; 2.0 clamps to 255
  writePng(dir_ / "out.png", image);
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load((dir_ / "out.png").c_str(), &w, &h, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  std::vector<int> rgba(pixels, pixels + 8);
  stbi_image_free(pixels);
  EXPECT_EQ(rgba, (std::vector<int>{188, 0, 255, 255, 0, 0, 0, 0}));
  EXPECT_EQ(files().size(), 1u);
}

TEST_F(ImageIo, FailedWritesNameTheFileAndLeaveNothing) {
  Image image(4, 4);
  const fs::path missing = dir_ / "no such folder" / "out.exr";
  try {
    writeExr(missing, image);
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(missing.string()));
  }
  EXPECT_THROW(writePng(dir_ / "no such folder" / "out.png", image), std::exception);
  EXPECT_TRUE(files().empty());
}

std::string contents(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(ImageIo, AnOutputSetIsWrittenWhole) {
  Image image = randomImage(5, 3);
  writeAllOrNothing({exrFile(dir_ / "out.exr", image), pngFile(dir_ / "out.png", image)});
  EXPECT_EQ(readExr(dir_ / "out.exr").beauty, image.beauty);
  EXPECT_EQ(files().size(), 2u) << "no temporary file may remain";
}

TEST_F(ImageIo, AFailedWriteInASetLeavesEveryExistingFileAsItWas) {
  std::ofstream(dir_ / "out.exr") << "old";
  Image image(4, 4);
  EXPECT_THROW(
      writeAllOrNothing({exrFile(dir_ / "out.exr", image), pngFile(dir_ / "no such folder" / "out.png", image)}),
      OutputError);
  const OutputFile failing{dir_ / "out.txt", [](const fs::path&) { throw std::runtime_error("disk full"); }};
  try {
    writeAllOrNothing({exrFile(dir_ / "out.exr", image), failing});
    FAIL() << "expected an error";
  } catch (const OutputError& e) {
    EXPECT_STREQ(e.what(), "disk full");
  }
  EXPECT_EQ(contents(dir_ / "out.exr"), "old");
  EXPECT_EQ(files().size(), 1u) << "no temporary file may remain";
}

TEST_F(ImageIo, OutputPathsAreCheckedBeforeAnythingIsWritten) {
  const auto errorOf = [](const fs::path& path) {
    try {
      checkOutputPath("-o", path);
    } catch (const OutputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(errorOf(""), "-o '': the output path is empty");
  EXPECT_EQ(errorOf(dir_), "-o '" + dir_.string() + "': is a folder; name a file in it");
  EXPECT_EQ(errorOf(dir_ / "missing" / "out.exr"), "-o '" + (dir_ / "missing" / "out.exr").string() +
                                                       "': the folder '" + (dir_ / "missing").string() +
                                                       "' does not exist");
  EXPECT_EQ(errorOf(dir_ / "out.exr"), "accepted");
  EXPECT_TRUE(files().empty());
}

TEST_F(ImageIo, ReadingAFileThatIsNotExrNamesIt) {
  std::ofstream(dir_ / "bad.exr") << "not an exr";
  try {
    readExr(dir_ / "bad.exr");
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), ::testing::AllOf(::testing::HasSubstr("bad.exr"), ::testing::HasSubstr("cannot read EXR")));
  }
}

TEST(ImageSize, ImpossibleSizesAreRejected) {
  EXPECT_THROW(Image(0, 10), std::invalid_argument);
  EXPECT_THROW(Image(10, -1), std::invalid_argument);
}

}  // namespace
}  // namespace facet
