#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/image/exr_file.h"
#include "engine/image/image_io.h"
#include "engine/image/png_chunks.h"
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

TEST_F(ImageIo, ChartPngsAreClippedSrgbAndOpaque) {
  Image image(2, 1);
  image.beauty[0] = {0.5f, 0.0f, 2.0f, 1.0f};  // 0.5 linear is 188 in sRGB; 2.0 clamps to 255
  writePng(dir_ / "out.png", image);
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load((dir_ / "out.png").c_str(), &w, &h, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  std::vector<int> rgba(pixels, pixels + 8);
  stbi_image_free(pixels);
  EXPECT_EQ(rgba, (std::vector<int>{188, 0, 255, 255, 0, 0, 0, 255}));
  EXPECT_EQ(files().size(), 1u);
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t bigEndian(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i) value = value << 8 | std::uint8_t(bytes[at + i]);
  return value;
}

// Every chunk's CRC checks (stb_image_write's own, from its table, against
// pngCrc's bitwise one), and sRGB, gAMA and cHRM precede the image data.
TEST_F(ImageIo, PngsCarryAnSrgbChunkWithValidCrcs) {
  writeAllOrNothing({pngFile(dir_ / "out.png", randomImage(7, 5))});
  const std::string png = contents(dir_ / "out.png");
  ASSERT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n");
  std::vector<std::string> types;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t length = bigEndian(png, at);
    ASSERT_LE(at + 12 + length, png.size());
    types.push_back(png.substr(at + 4, 4));
    EXPECT_EQ(bigEndian(png, at + 8 + length),
              pngCrc(reinterpret_cast<const std::uint8_t*>(png.data()) + at + 4, 4 + length))
        << types.back();
    if (types.back() == "sRGB") {
      EXPECT_EQ(length, 1u);
      EXPECT_EQ(png[at + 8], 0) << "perceptual rendering intent";
    }
    if (types.back() == "gAMA") {
      EXPECT_EQ(bigEndian(png, at + 8), 45455u);
    }
    at += 12 + length;
  }
  ASSERT_GE(types.size(), 5u);
  EXPECT_EQ(std::vector<std::string>(types.begin(), types.begin() + 5),
            (std::vector<std::string>{"IHDR", "sRGB", "gAMA", "cHRM", "IDAT"}));
  EXPECT_EQ(types.back(), "IEND");
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

// checkOutputPath's message for `path`, or "accepted".
std::string outputPathError(const fs::path& path) {
  try {
    checkOutputPath("-o", path);
  } catch (const OutputError& e) {
    return std::string(e.what());
  }
  return std::string("accepted");
}

TEST_F(ImageIo, OutputPathsAreCheckedBeforeAnythingIsWritten) {
  const auto errorOf = outputPathError;
  EXPECT_EQ(errorOf(""), "-o '': the output path is empty");
  EXPECT_EQ(errorOf(dir_), "-o '" + dir_.string() + "': is a folder; name a file in it");
  EXPECT_EQ(errorOf(dir_ / "missing" / "out.exr"), "-o '" + (dir_ / "missing" / "out.exr").string() +
                                                       "': the folder '" + (dir_ / "missing").string() +
                                                       "' does not exist");
  EXPECT_EQ(errorOf(dir_ / "out.exr"), "accepted");
  EXPECT_TRUE(files().empty());
}

TEST_F(ImageIo, OutputsReplaceOnlyRegularFiles) {
  const auto rejected = outputPathError;
  std::ofstream(dir_ / "target.exr") << "kept";
  fs::create_symlink(dir_ / "target.exr", dir_ / "link.exr");
  EXPECT_NE(rejected(dir_ / "link.exr").find("is a symbolic link"), std::string::npos);
  fs::create_symlink(dir_ / "nowhere.exr", dir_ / "dangling.exr");
  EXPECT_NE(rejected(dir_ / "dangling.exr").find("is a symbolic link"), std::string::npos);
  ASSERT_EQ(mkfifo((dir_ / "fifo.exr").c_str(), 0600), 0);
  EXPECT_NE(rejected(dir_ / "fifo.exr").find("is a device, FIFO or socket"), std::string::npos);
  EXPECT_NE(rejected("/dev/null").find("is a device, FIFO or socket"), std::string::npos);
  EXPECT_EQ(rejected(dir_ / "target.exr"), "accepted");
  EXPECT_EQ(contents(dir_ / "target.exr"), "kept");
}

TEST_F(ImageIo, TheExtensionChoosesTheFormat) {
  EXPECT_NO_THROW(checkOutputExtension("-o", dir_ / "a.EXR", ".exr"));
  EXPECT_THROW(checkOutputExtension("-o", dir_ / "a.png", ".exr"), OutputError);
  EXPECT_THROW(checkOutputExtension("--png", dir_ / "a", ".png"), OutputError);
}

TEST_F(ImageIo, TwoSpellingsOfOneFileAreTheSameFile) {
  std::ofstream(dir_ / "tile.exr") << "tile";
  fs::create_symlink(dir_ / "tile.exr", dir_ / "alias.exr");
  EXPECT_TRUE(namesSameFile(dir_ / "tile.exr", dir_ / "." / "tile.exr"));
  EXPECT_TRUE(namesSameFile(dir_ / "alias.exr", dir_ / "tile.exr"));
  EXPECT_TRUE(namesSameFile(dir_ / "new.exr", dir_ / "sub" / ".." / "new.exr"));
  EXPECT_FALSE(namesSameFile(dir_ / "tile.exr", dir_ / "other.exr"));
}

TEST_F(ImageIo, ANameTooLongForItsTemporaryIsRefusedBeforeTheWork) {
  EXPECT_EQ(outputPathError(dir_ / (std::string(225, 'a') + ".exr")), "accepted");
  EXPECT_NE(outputPathError(dir_ / (std::string(226, 'a') + ".exr")).find("the file name is 230 bytes, more than 229"),
            std::string::npos);
}

TEST_F(ImageIo, TemporariesOfAKilledWriterAreRemovedByTheNextWrite) {
  // pid_max is at most 2^22, so no process has this pid; this process's is alive.
  const fs::path orphan = dir_ / "out.exr.tmp-999999999-17";
  const fs::path live = dir_ / ("out.exr.tmp-" + std::to_string(getpid()) + "-17");
  const fs::path otherOutput = dir_ / "other.exr.tmp-999999999-17";
  for (const fs::path& file : {orphan, live, otherOutput}) std::ofstream(file) << "partial";
  writeAllOrNothing({exrFile(dir_ / "out.exr", Image(2, 2))});
  EXPECT_FALSE(fs::exists(orphan));
  EXPECT_TRUE(fs::exists(live)) << "a running writer's temporary is its own";
  EXPECT_TRUE(fs::exists(otherOutput)) << "only the destinations written are swept";
}

TEST_F(ImageIo, AFullDiskIsNamedAsSuch) {
  try {
    writeBytes("/dev/full", std::vector<std::uint8_t>(4096, 1), "preview.png");
    FAIL() << "writing to /dev/full succeeded";
  } catch (const OutputError& e) {
    EXPECT_STREQ(e.what(), "preview.png: cannot write: No space left on device");
  }
}

TEST(ImageSize, ImpossibleSizesAreRejected) {
  EXPECT_THROW(Image(0, 10), std::invalid_argument);
  EXPECT_THROW(Image(10, -1), std::invalid_argument);
}

}  // namespace
}  // namespace facet
