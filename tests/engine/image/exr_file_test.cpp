// The EXR writer: every plane round trips bit for bit, --aovs chooses the
// layers, a half beauty is half and nothing else is, and the header holds
// the camera, the settings and the Cryptomatte entries of the ID layers.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <half.h>
#include <nlohmann/json.hpp>

#include <bit>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/image/cryptomatte.h"
#include "engine/image/exr_file.h"
#include "tests/support/random_image.h"
#include "tests/support/temp_dir.h"

namespace facet {
namespace {

namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

class ExrFile : public testing::TempDirTest {
 protected:
  std::vector<fs::path> files() const { return {fs::directory_iterator(dir_), fs::directory_iterator()}; }

  // Channel name to its type in the file.
  std::map<std::string, Imf::PixelType> channels(const fs::path& path) {
    Imf::InputFile file(path.c_str());
    std::map<std::string, Imf::PixelType> types;
    for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c)
      types[c.name()] = c.channel().type;
    return types;
  }

  std::vector<std::string> channelNames(const fs::path& path) {
    std::vector<std::string> names;
    for (const auto& [name, type] : channels(path)) names.push_back(name);
    return names;
  }
};

// Two objects, "ball" (faces 0..5) and "box" (faces 6..11), both of
// material 1, "gold"; the image's pixels hit face 3, face 7, or nothing.
ExrNames twoObjects() { return {{"ball", "box"}, {0, 6}, {1, 1}, {"paint", "gold"}}; }

Image hittingTwoObjects() {
  Image image(3, 2);
  image.faceId = {3, 7, Image::kNoId, 0, 11, Image::kNoId};
  for (std::size_t i = 0; i < image.pixelCount(); ++i)
    if (image.faceId[i] != Image::kNoId) image.beauty[i] = {0.25f * float(i), 0.5f, 1.0f / 3.0f, 1.0f};
  return image;
}

TEST_F(ExrFile, RoundTripKeepsEveryChannelBitExact) {
  Image image = testing::randomImage(37, 19);
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

TEST_F(ExrFile, ReadingAFileThatIsNotExrNamesIt) {
  std::ofstream(dir_ / "bad.exr") << "not an exr";
  try {
    readExr(dir_ / "bad.exr");
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), ::testing::AllOf(HasSubstr("bad.exr"), HasSubstr("cannot read EXR")));
  }
}

TEST(ExrLayerNames, ParseAllBeautyOrAListThatAlwaysHoldsTheBeauty) {
  EXPECT_EQ(parseExrLayers("all", "--aovs"),
            (ExrLayers{"beauty", "depth", "position", "normals", "ids", "uv", "texcoord", "crypto"}));
  EXPECT_EQ(parseExrLayers("beauty", "--aovs"), ExrLayers{"beauty"});
  EXPECT_EQ(parseExrLayers("depth,crypto", "--aovs"), (ExrLayers{"beauty", "depth", "crypto"}));
  try {
    parseExrLayers("depth,albedo", "--aovs");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "--aovs 'depth,albedo': expected all, or a comma-separated list of: beauty, depth, position, "
                 "normals, ids, uv, texcoord, crypto");
  }
  EXPECT_THROW(parseExrLayers("", "--aovs"), std::invalid_argument);
  EXPECT_THROW(parseExrLayers("depth,", "--aovs"), std::invalid_argument);
}

TEST_F(ExrFile, TheLayersChosenAreTheChannelsWritten) {
  const Image image = hittingTwoObjects();
  ExrOptions options;
  options.metadata.names = twoObjects();
  writeExr(dir_ / "all.exr", image, options);
  EXPECT_THAT(channelNames(dir_ / "all.exr"),
              ElementsAre("A", "B", "CryptoMaterial00.A", "CryptoMaterial00.B", "CryptoMaterial00.G",
                          "CryptoMaterial00.R", "CryptoObject00.A", "CryptoObject00.B", "CryptoObject00.G",
                          "CryptoObject00.R", "G", "N.X", "N.Y", "N.Z", "Ng.X", "Ng.Y", "Ng.Z", "P.X", "P.Y", "P.Z",
                          "R", "Z", "faceId", "materialId", "objectId", "patchId", "st.s", "st.t", "uv.U", "uv.V"));
  options.layers = parseExrLayers("beauty", "--aovs");
  writeExr(dir_ / "beauty.exr", image, options);
  EXPECT_THAT(channelNames(dir_ / "beauty.exr"), ElementsAre("A", "B", "G", "R"));
  options.layers = parseExrLayers("depth,ids", "--aovs");
  writeExr(dir_ / "ids.exr", image, options);
  EXPECT_THAT(channelNames(dir_ / "ids.exr"),
              ElementsAre("A", "B", "G", "R", "Z", "faceId", "materialId", "objectId", "patchId"));
  Imf::InputFile file((dir_ / "ids.exr").c_str());
  EXPECT_EQ(
      file.header().findTypedAttribute<Imf::StringAttribute>("cryptomatte/" + cryptomatteKey("CryptoObject") + "/name"),
      nullptr)
      << "no Cryptomatte entries without its layer";
}

TEST_F(ExrFile, AHalfBeautyIsHalfAndEveryOtherChannelKeepsItsType) {
  const Image image = hittingTwoObjects();
  ExrOptions options;
  options.metadata.names = twoObjects();
  options.halfBeauty = true;
  writeExr(dir_ / "half.exr", image, options);
  for (const auto& [name, type] : channels(dir_ / "half.exr")) {
    const bool beauty = name.size() == 1 && std::string("RGBA").find(name) != std::string::npos;
    const bool id = name.ends_with("Id");
    EXPECT_EQ(type, beauty ? Imf::HALF : id ? Imf::UINT : Imf::FLOAT) << name;
  }
  const Image back = readExr(dir_ / "half.exr");
  for (std::size_t i = 0; i < image.pixelCount(); ++i)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(back.beauty[i][c], float(half(image.beauty[i][c]))) << i << ' ' << c;
  EXPECT_EQ(back.faceId, image.faceId);
}

TEST_F(ExrFile, TheHeaderHoldsTheCameraTheSoftwareAndTheSettings) {
  ExrOptions options;
  ExrCamera camera{{1.0, 2.0, 3.0}, {0.0, 0.0, -1.0}, {0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}, 0.5, 1.5};
  options.metadata = {camera, {"facet 9.8.7", "backend=cpu spp=4", "0123456789abcdef", 4000000000u}, std::nullopt};
  writeExr(dir_ / "camera.exr", hittingTwoObjects(), options);
  Imf::InputFile file((dir_ / "camera.exr").c_str());
  const Imf::Header& header = file.header();
  ASSERT_TRUE(Imf::hasWorldToCamera(header));
  ASSERT_TRUE(Imf::hasWorldToNDC(header));
  const Imath::M44f toCamera = Imf::worldToCamera(header), toNdc = Imf::worldToNDC(header);
  const RowMatrix expectedCamera = worldToCamera(camera), expectedNdc = worldToNdc(camera);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      EXPECT_EQ(toCamera[i][j], float(expectedCamera[i][j])) << i << j;
      EXPECT_EQ(toNdc[i][j], float(expectedNdc[i][j])) << i << j;
    }
  // Imath's row vectors: the eye goes to the camera's origin.
  EXPECT_EQ(Imath::V3f(1.0f, 2.0f, 3.0f) * toCamera, Imath::V3f(0.0f));
  EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("software").value(), "facet 9.8.7");
  EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>(kRenderSettingsAttribute).value(), "backend=cpu spp=4");
  const ExrProvenance back = readExrProvenance(dir_ / "camera.exr");
  EXPECT_EQ(back.software, "facet 9.8.7");
  EXPECT_EQ(back.renderSettings, "backend=cpu spp=4");
  EXPECT_EQ(back.pictureDigest, "0123456789abcdef");
  EXPECT_EQ(back.estimateSeed, 4000000000u);  // all 32 bits through OpenEXR's signed attribute
}

TEST_F(ExrFile, AnImageThatIsNoEstimateRecordsNoSeed) {
  ExrOptions options;
  options.metadata.provenance = {"facet 9.8.7", "backend=cpu spp=1", "0123456789abcdef", std::nullopt};
  writeExr(dir_ / "unseeded.exr", hittingTwoObjects(), options);
  const ExrProvenance back = readExrProvenance(dir_ / "unseeded.exr");
  EXPECT_EQ(back.pictureDigest, "0123456789abcdef");
  EXPECT_FALSE(back.estimateSeed.has_value());
}

TEST_F(ExrFile, IdLayersNameEachPixelsObjectAndMaterial) {
  const Image image = hittingTwoObjects();
  ExrOptions options;
  options.metadata.names = twoObjects();
  writeExr(dir_ / "ids.exr", image, options);
  Imf::InputFile file((dir_ / "ids.exr").c_str());
  const Imf::Header& header = file.header();

  std::vector<std::uint32_t> objectId(6), materialId(6);
  std::vector<float> id(6), coverage(6), rank1(6), coverage1(6);
  Imf::FrameBuffer frame;
  const auto insert = [&](const char* name, Imf::PixelType type, auto& plane) {
    frame.insert(name, Imf::Slice(type, reinterpret_cast<char*>(plane.data()), 4, 12));
  };
  insert("objectId", Imf::UINT, objectId);
  insert("materialId", Imf::UINT, materialId);
  insert("CryptoObject00.R", Imf::FLOAT, id);
  insert("CryptoObject00.G", Imf::FLOAT, coverage);
  insert("CryptoObject00.B", Imf::FLOAT, rank1);
  insert("CryptoObject00.A", Imf::FLOAT, coverage1);
  file.setFrameBuffer(frame);
  file.readPixels(0, 1);
  constexpr std::uint32_t no = Image::kNoId;
  EXPECT_THAT(objectId, ElementsAre(0u, 1u, no, 0u, 1u, no));
  EXPECT_THAT(materialId, ElementsAre(1u, 1u, no, 1u, 1u, no));
  const float ball = cryptomatteId("ball"), box = cryptomatteId("box");
  EXPECT_THAT(id, ElementsAre(ball, box, 0.0f, ball, box, 0.0f));  // 0: no object, as the spec says
  EXPECT_THAT(coverage, ElementsAre(1.0f, 1.0f, 0.0f, 1.0f, 1.0f, 0.0f));
  EXPECT_THAT(rank1, ::testing::Each(0.0f));
  EXPECT_THAT(coverage1, ::testing::Each(0.0f));

  for (const auto& [layer, names] : {std::pair{"CryptoObject", std::vector<std::string>{"ball", "box"}},
                                     std::pair{"CryptoMaterial", std::vector<std::string>{"paint", "gold"}}}) {
    const std::string prefix = "cryptomatte/" + cryptomatteKey(layer) + "/";
    const auto text = [&](const std::string& key) {
      return header.typedAttribute<Imf::StringAttribute>(prefix + key).value();
    };
    EXPECT_EQ(text("name"), layer);
    EXPECT_EQ(text("hash"), "MurmurHash3_32");
    EXPECT_EQ(text("conversion"), "uint32_to_float32");
    const nlohmann::json manifest = nlohmann::json::parse(text("manifest"));
    ASSERT_EQ(manifest.size(), names.size());
    for (const std::string& name : names) EXPECT_EQ(manifest.at(name), cryptomatteHex(cryptomatteId(name))) << name;
  }
}

}  // namespace
}  // namespace facet
