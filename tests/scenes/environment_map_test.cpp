#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <stb_image_write.h>  // implemented in facet_image

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "scenes/environment_map.h"
#include "scenes/input_error.h"
#include "tests/support/temp_dir.h"

namespace facet::scene {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

const fs::path kEnvironments = FACET_ENVIRONMENTS_DIR;

class EnvironmentMaps : public facet::testing::TempDirTest {
 protected:
  // A FLOAT scanline EXR of the given channels (each width x height values),
  // its data window starting at `origin`.
  fs::path writeExr(const std::string& name, int width, int height,
                    const std::map<std::string, std::vector<float>>& channels, Imath::V2i origin = {0, 0}) {
    const fs::path path = dir_ / name;
    const Imath::Box2i window(origin, origin + Imath::V2i(width - 1, height - 1));
    Imf::Header header(Imath::Box2i({0, 0}, {width - 1, height - 1}), window);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    for (const auto& [channel, values] : channels) {
      header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
      frame.insert(channel, Imf::Slice::Make(Imf::FLOAT, values.data(), window));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(height);
    return path;
  }

  fs::path writeRgbExr(const std::string& name, int width, int height, const std::vector<float>& rgb) {
    std::vector<float> r, g, b;
    for (std::size_t i = 0; i < rgb.size(); i += 3) {
      r.push_back(rgb[i]);
      g.push_back(rgb[i + 1]);
      b.push_back(rgb[i + 2]);
    }
    return writeExr(name, width, height, {{"R", r}, {"G", g}, {"B", b}});
  }

  fs::path writeHdr(const std::string& name, int width, int height, const std::vector<float>& rgb) {
    const fs::path path = dir_ / name;
    EXPECT_NE(stbi_write_hdr(path.c_str(), width, height, 3, rgb.data()), 0);
    return path;
  }

  fs::path writeBytes(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return dir_ / name;
  }

  static std::string bytesOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }

  static std::string errorOf(const fs::path& path) {
    try {
      loadEnvironmentMap(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

// Radiance over several orders of magnitude, as real maps have.
std::vector<float> randomRadiance(int width, int height, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> exponent(-4.0f, 4.0f);
  std::vector<float> rgb(3 * std::size_t(width) * std::size_t(height));
  for (float& x : rgb) x = std::exp2(exponent(random));
  return rgb;
}

void expectFiniteAndNonNegative(const EnvironmentMap& map) {
  ASSERT_EQ(map.rgb.size(), 3 * std::size_t(map.width) * std::size_t(map.height));
  std::size_t bad = 0;
  for (float x : map.rgb) bad += std::isfinite(x) && x >= 0 ? 0 : 1;
  EXPECT_EQ(bad, 0u);
}

TEST_F(EnvironmentMaps, TheShippedMapsLoad) {
  const EnvironmentMap courtyard = loadEnvironmentMap(kEnvironments / "courtyard_256x128.hdr");
  EXPECT_EQ(courtyard.width, 256);
  EXPECT_EQ(courtyard.height, 128);
  EXPECT_EQ(courtyard.source, kEnvironments / "courtyard_256x128.hdr");
  EXPECT_EQ(courtyard.clampedTexels, 0u);  // RGBE cannot hold a negative or non-finite value
  expectFiniteAndNonNegative(courtyard);

  const EnvironmentMap sunrise = loadEnvironmentMap(kEnvironments / "sunrise.exr");
  EXPECT_EQ(sunrise.width, 1024);
  EXPECT_EQ(sunrise.height, 512);
  expectFiniteAndNonNegative(sunrise);
  // DWAB's small negative ringing is zeroed, but only around a few features.
  EXPECT_LT(sunrise.clampedTexels, std::size_t(sunrise.width * sunrise.height) / 10);
  float brightest = 0;
  for (int y = 0; y < sunrise.height; ++y)
    for (int x = 0; x < sunrise.width; ++x) brightest = std::max(brightest, luminance(sunrise.texel(x, y)));
  EXPECT_GT(brightest, 1000.0f);
}

TEST_F(EnvironmentMaps, TheExtensionIsCaseInsensitive) {
  fs::copy_file(kEnvironments / "courtyard_256x128.hdr", dir_ / "courtyard.HDR");
  EXPECT_EQ(loadEnvironmentMap(dir_ / "courtyard.HDR").rgb,
            loadEnvironmentMap(kEnvironments / "courtyard_256x128.hdr").rgb);
}

TEST_F(EnvironmentMaps, TheHashFollowsTheContentNotTheFile) {
  const EnvironmentMap a = loadEnvironmentMap(kEnvironments / "courtyard_256x128.hdr");
  fs::copy_file(kEnvironments / "courtyard_256x128.hdr", dir_ / "copy.hdr");
  const EnvironmentMap b = loadEnvironmentMap(dir_ / "copy.hdr");
  EXPECT_EQ(a.contentHash(), b.contentHash());

  EnvironmentMap changed = a;
  changed.rgb[3 * (7 * 256 + 100) + 1] *= 1.001f;
  EXPECT_NE(changed.contentHash(), a.contentHash());

  // The same floats in another shape are another map.
  EnvironmentMap reshaped = constantEnvironment({1, 2, 3});
  std::swap(reshaped.width, reshaped.height);
  EXPECT_NE(reshaped.contentHash(), constantEnvironment({1, 2, 3}).contentHash());
  EXPECT_EQ(constantEnvironment({1, 2, 3}).contentHash(), constantEnvironment({1, 2, 3}).contentHash());
}

TEST_F(EnvironmentMaps, AConstantEnvironmentIsEightByFourTexelsOfItsColour) {
  const EnvironmentMap map = constantEnvironment({0.25, 1.5, 3.0});
  EXPECT_EQ(map.width, 8);
  EXPECT_EQ(map.height, 4);
  EXPECT_TRUE(map.source.empty());
  ASSERT_EQ(map.rgb.size(), 3u * 8 * 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_EQ(map.texel(x, y), glm::vec3(0.25f, 1.5f, 3.0f));
}

TEST_F(EnvironmentMaps, NegativeAndNonFiniteChannelsAreZeroedAndCounted) {
  const int width = 8, height = 4;
  std::vector<float> rgb(3 * width * height);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = 0.5f + float(i);
  auto at = [&](int x, int y, int c) -> float& { return rgb[std::size_t(3 * (y * width + x) + c)]; };
  at(1, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  at(2, 1, 1) = std::numeric_limits<float>::infinity();
  at(3, 2, 2) = -1.0f;
  const std::vector<float> original = rgb;

  const EnvironmentMap map = loadEnvironmentMap(writeRgbExr("bad.exr", width, height, rgb));
  EXPECT_EQ(map.clampedTexels, 3u);
  EXPECT_EQ(map.texel(1, 0), glm::vec3(0.0f, original[4], original[5]));
  EXPECT_EQ(map.texel(2, 1), glm::vec3(original[30], 0.0f, original[32]));
  EXPECT_EQ(map.texel(3, 2), glm::vec3(original[57], original[58], 0.0f));
  std::size_t intact = 0;
  for (std::size_t i = 0; i < rgb.size(); ++i) intact += map.rgb[i] == original[i] ? 1 : 0;
  EXPECT_EQ(intact, rgb.size() - 3);
}

// Float sums over the map would overflow: such a map is refused, not zeroed.
TEST_F(EnvironmentMaps, RadianceAbove1e30IsRefused) {
  std::vector<float> rgb(3 * 8 * 4, 1.0f);
  rgb[3 * 9] = 1e30f;
  EXPECT_EQ(loadEnvironmentMap(writeRgbExr("at_the_bound.exr", 8, 4, rgb)).clampedTexels, 0u);
  rgb[3 * 9 + 1] = 3e38f;
  EXPECT_THAT(errorOf(writeRgbExr("near_float_max.exr", 8, 4, rgb)),
              AllOf(HasSubstr("near_float_max.exr: environment radiance must be at most 1e30"),
                    HasSubstr("texel (1, 1)")));
  // RGBE's largest exponent: a mantissa of 255 times 2^119.
  std::string pixels;
  for (int i = 0; i < 8 * 4; ++i) pixels += i == 3 ? std::string("\xff\x80\x80\xff", 4) : std::string("\x80\x80\x80\x81", 4);
  EXPECT_THAT(errorOf(writeBytes("exponent_255.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n" + pixels)),
              AllOf(HasSubstr("exponent_255.hdr: environment radiance must be at most 1e30"),
                    HasSubstr("texel (3, 0)")));
}

TEST_F(EnvironmentMaps, TheDataWindowIsTheMap) {
  const int width = 8, height = 4;
  std::vector<float> r(width * height), g(width * height), b(width * height);
  for (int i = 0; i < width * height; ++i) {
    r[std::size_t(i)] = float(i);
    g[std::size_t(i)] = float(2 * i);
    b[std::size_t(i)] = float(3 * i);
  }
  const EnvironmentMap map =
      loadEnvironmentMap(writeExr("offset.exr", width, height, {{"R", r}, {"G", g}, {"B", b}}, {-3, 5}));
  ASSERT_EQ(map.width, width);
  ASSERT_EQ(map.height, height);
  EXPECT_EQ(map.texel(0, 0), glm::vec3(0, 0, 0));
  EXPECT_EQ(map.texel(5, 2), glm::vec3(21, 42, 63));
  EXPECT_EQ(map.texel(7, 3), glm::vec3(31, 62, 93));
}

TEST_F(EnvironmentMaps, ALuminanceOnlyExrIsGrey) {
  std::vector<float> y(8 * 4);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = float(i) / 4;
  const EnvironmentMap map = loadEnvironmentMap(writeExr("grey.exr", 8, 4, {{"Y", y}}));
  EXPECT_EQ(map.texel(6, 2), glm::vec3(y[22]));
}

TEST_F(EnvironmentMaps, RadianceFilesRoundTrip) {
  // 16 wide is run-length encoded; below 8 wide the file is flat.
  for (const auto& [width, height] : {std::pair{16, 8}, std::pair{4, 2}}) {
    const std::vector<float> rgb = randomRadiance(width, height, unsigned(width));
    const EnvironmentMap map = loadEnvironmentMap(writeHdr("map" + std::to_string(width) + ".hdr", width, height, rgb));
    ASSERT_EQ(map.width, width);
    ASSERT_EQ(map.height, height);
    EXPECT_EQ(map.clampedTexels, 0u);
    // RGBE: an 8-bit mantissa per channel under the texel's largest exponent.
    for (std::size_t i = 0; i < rgb.size(); i += 3) {
      const float scale = std::max({rgb[i], rgb[i + 1], rgb[i + 2]});
      for (std::size_t c = i; c < i + 3; ++c) EXPECT_NEAR(map.rgb[c], rgb[c], scale / 128) << "value " << c;
    }
  }
}

TEST_F(EnvironmentMaps, ErrorsNameTheFileAndTheRule) {
  EXPECT_THAT(errorOf(dir_ / "missing.exr"),
              AllOf(HasSubstr("missing.exr"), HasSubstr("cannot open the environment map")));
  EXPECT_THAT(errorOf(writeBytes("map.png", "\x89PNG")),
              AllOf(HasSubstr("map.png"), HasSubstr("unknown environment map format"), HasSubstr(".exr")));
  EXPECT_THAT(errorOf(writeRgbExr("wide.exr", 12, 4, std::vector<float>(3 * 12 * 4, 1.0f))),
              AllOf(HasSubstr("wide.exr"), HasSubstr("must be 2:1"), HasSubstr("12 x 4")));
  EXPECT_THAT(errorOf(writeHdr("wide.hdr", 12, 4, std::vector<float>(3 * 12 * 4, 1.0f))),
              AllOf(HasSubstr("wide.hdr"), HasSubstr("must be 2:1"), HasSubstr("12 x 4")));

  std::mt19937 random(7);
  std::string garbage(4096, '\0');
  for (char& c : garbage) c = char(random());
  EXPECT_THAT(errorOf(writeBytes("garbage.exr", garbage)),
              AllOf(HasSubstr("garbage.exr"), HasSubstr("cannot read the OpenEXR file")));
  EXPECT_THAT(errorOf(writeBytes("garbage.hdr", garbage)),
              AllOf(HasSubstr("garbage.hdr"), HasSubstr("not a valid Radiance .hdr file")));

  const std::string hdr = bytesOf(writeHdr("whole.hdr", 64, 32, randomRadiance(64, 32, 1)));
  EXPECT_THAT(errorOf(writeBytes("truncated.hdr", hdr.substr(0, hdr.size() / 2))),
              AllOf(HasSubstr("truncated.hdr"), HasSubstr("not a valid Radiance .hdr file"), HasSubstr("truncated")));
  const std::string exr = bytesOf(writeRgbExr("whole.exr", 64, 32, randomRadiance(64, 32, 2)));
  EXPECT_THAT(errorOf(writeBytes("truncated.exr", exr.substr(0, exr.size() / 2))),
              AllOf(HasSubstr("truncated.exr"), HasSubstr("cannot read the OpenEXR file")));
}

TEST_F(EnvironmentMaps, HeadersAreCheckedBeforeAnyPixelIsRead) {
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";
  EXPECT_THAT(errorOf(writeBytes("huge.hdr", header + "-Y 8193 +X 16386\n")),
              AllOf(HasSubstr("huge.hdr"), HasSubstr("at most 16384 x 8192")));
  // Twice this height overflows a 64-bit integer.
  EXPECT_THAT(errorOf(writeBytes("tall.hdr", header + "-Y 9223372036854775807 +X 2\n")),
              AllOf(HasSubstr("tall.hdr"), HasSubstr("must be 2:1")));
  EXPECT_THAT(errorOf(writeBytes("empty.hdr", header + "-Y 0 +X 0\n")),
              AllOf(HasSubstr("empty.hdr"), HasSubstr("must not be empty")));
  EXPECT_THAT(errorOf(writeBytes("flipped.hdr", header + "+Y 4 +X 8\n")),
              AllOf(HasSubstr("flipped.hdr"), HasSubstr("-Y <height> +X <width>")));
  // A zero run length would make stb_image loop forever.
  EXPECT_THAT(errorOf(writeBytes("zero_run.hdr", header + "-Y 4 +X 8\n" + std::string("\x02\x02\x00\x08\x00", 5))),
              AllOf(HasSubstr("zero_run.hdr"), HasSubstr("bad run-length data")));
}

TEST_F(EnvironmentMaps, ExrHeadersAreCheckedBeforeOpenExrAllocatesFromThem) {
  // After the magic and version: an attribute that claims 1.6 GB, holding 4 bytes.
  const std::string exr = bytesOf(writeRgbExr("whole.exr", 8, 4, std::vector<float>(96, 1.0f)));
  const std::int32_t claimed = 1634692198;
  const std::string attribute =
      std::string("comment\0opaque\0", 15) + std::string(reinterpret_cast<const char*>(&claimed), 4) + "xxxx";
  EXPECT_THAT(errorOf(writeBytes("claims.exr", exr.substr(0, 8) + attribute + exr.substr(8))),
              AllOf(HasSubstr("claims.exr"),
                    HasSubstr("attribute 'comment' (opaque) claims 1634692198 bytes, more than the file holds")));
  // OpenEXR reads a channel list to its empty name, whatever its size says.
  std::string longer = exr;
  const std::size_t channels = longer.find(std::string("channels\0chlist\0", 16)) + 16;
  longer[channels] = char(longer[channels] + 1);
  EXPECT_THAT(errorOf(writeBytes("channels.exr", longer)), HasSubstr("attribute 'channels' (chlist) claims"));
  EXPECT_EQ(loadEnvironmentMap(writeBytes("copy.exr", exr)).width, 8);
}

TEST_F(EnvironmentMaps, ExrFilesNeedColourChannels) {
  EXPECT_THAT(errorOf(writeExr("depth.exr", 8, 4, {{"Z", std::vector<float>(32, 1.0f)}})),
              AllOf(HasSubstr("depth.exr"), HasSubstr("needs channels R, G and B (or Y)"), HasSubstr("has Z")));
  EXPECT_THAT(errorOf(writeExr("red.exr", 8, 4, {{"R", std::vector<float>(32, 1.0f)}})),
              AllOf(HasSubstr("red.exr"), HasSubstr("needs channels R, G and B")));
}

}  // namespace
}  // namespace facet::scene
