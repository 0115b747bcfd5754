// glTF textures: PNG images decode (through facet's decoder, with its checks
// before a texel is decoded), and a material's texture slots, samplers and
// transforms arrive as the file says.
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_gltf.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace facet::scene {
namespace {

using facet::testing::Rgba8;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
namespace t = rules::f64;

class GltfTextures : public facet::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    // sRGB 188 is linear 0.5029; 0 and 255 are exact.
    ASSERT_TRUE(facet::testing::writePng(dir_ / "base.png", 4, 4,
                                         facet::testing::checkerTexels(4, 2, {188, 0, 255, 255}, {0, 255, 0, 128})));
    ASSERT_TRUE(facet::testing::writePng(dir_ / "mr.png", 2, 2, std::vector<Rgba8>(4, Rgba8{0, 128, 255, 255})));
  }

  // Material 0 reads base.png as its base colour and mr.png as its
  // metallic-roughness; `material` and `extra` add to or replace the file's members.
  nlohmann::json parts(const nlohmann::json& material = nlohmann::json::object()) {
    nlohmann::json m = {
        {"pbrMetallicRoughness",
         {{"baseColorTexture",
           {{"index", 0},
            {"extensions",
             {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"rotation", 0.5}, {"scale", {2, 3}}}}}}}},
          {"metallicRoughnessTexture", {{"index", 1}}},
          {"roughnessFactor", 0.5}}},
        {"normalTexture", {{"index", 1}, {"scale", 0.75}}}};
    m.update(material);
    return {{"materials", {m}},
            {"textures", {{{"source", 0}, {"sampler", 0}}, {{"source", 1}}}},
            {"samplers", {{{"magFilter", 9728}, {"minFilter", 9986}, {"wrapS", 33071}, {"wrapT", 33648}}}},
            {"images", {{{"uri", "base.png"}}, {{"uri", "mr.png"}}}}};
  }
};

TEST_F(GltfTextures, PngImagesDecodeIntoTheMaterialsSlots) {
  const Scene scene = loadScene(facet::testing::writeTexturedQuad(dir_, "quad", parts()));
  ASSERT_TRUE(scene.materials.at(0).textures.has_value());
  const materials::MaterialTextures& m = *scene.materials[0].textures;
  EXPECT_DOUBLE_EQ(m.roughness, 0.5);
  EXPECT_DOUBLE_EQ(m.normalScale, 0.75);
  // Texture 1 serves as data twice (one texture) and never as colour.
  ASSERT_EQ(scene.textures.size(), 2u);
  EXPECT_EQ(m.metallicRoughnessTexture.texture, m.normalTexture.texture);
  EXPECT_EQ(m.occlusionTexture.texture, -1);
  EXPECT_EQ(m.emissiveTexture.texture, -1);
  const materials::TextureSlot& base = m.baseColorTexture;
  EXPECT_EQ(base.offset, glm::dvec2(0.5, 0.25));
  EXPECT_EQ(base.scale, glm::dvec2(2, 3));
  EXPECT_DOUBLE_EQ(base.rotation, 0.5);

  const Texture& colour = scene.textures.at(std::size_t(base.texture));
  ASSERT_EQ(colour.levels.size(), 3u);  // 4 x 4, 2 x 2, 1 x 1
  EXPECT_EQ(colour.levels[2].width, 1);
  const glm::vec4 even = colour.levels[0].texels[0], odd = colour.levels[0].texels[2];
  EXPECT_NEAR(even.r, 0.50289, 1e-4);  // sRGB decoded
  EXPECT_EQ(even.g, 0.0f);
  EXPECT_EQ(even.b, 1.0f);
  EXPECT_EQ(even.a, 1.0f);
  EXPECT_NEAR(odd.a, 128.0 / 255.0, 1e-6);  // alpha stays linear
  // Each coarser level averages the linear values.
  EXPECT_NEAR(colour.levels[2].texels[0].r, 0.5 * 0.50289, 1e-4);
  EXPECT_EQ(colour.sampler.magFilter, t::FACET_FILTER_NEAREST);
  EXPECT_EQ(colour.sampler.minFilter, t::FACET_FILTER_NEAREST);
  EXPECT_EQ(colour.sampler.mipMode, t::FACET_MIP_LINEAR);
  EXPECT_EQ(colour.sampler.wrapS, t::FACET_WRAP_CLAMP_TO_EDGE);
  EXPECT_EQ(colour.sampler.wrapT, t::FACET_WRAP_MIRRORED_REPEAT);

  const Texture& data = scene.textures.at(std::size_t(m.metallicRoughnessTexture.texture));
  EXPECT_NEAR(data.levels[0].texels[0].g, 128.0 / 255.0, 1e-6);  // not decoded
  EXPECT_EQ(data.sampler.mipMode, t::FACET_MIP_LINEAR);          // glTF viewers' default
  EXPECT_EQ(data.sampler.wrapS, t::FACET_WRAP_REPEAT);
}

// Files name one image in many textures (a test sheet: one texture per
// material over a few images); those are one texture, not a copy each.
TEST_F(GltfTextures, TexturesOfOneImageAndSamplerAreOneTexture) {
  nlohmann::json file = parts({{"occlusionTexture", {{"index", 2}}}, {"normalTexture", {{"index", 3}}}});
  // 2 is texture 1 again (mr.png, no sampler); 3 is mr.png with sampler 0.
  file["textures"].push_back({{"source", 1}});
  file["textures"].push_back({{"source", 1}, {"sampler", 0}});
  const Scene scene = loadScene(facet::testing::writeTexturedQuad(dir_, "quad", file));
  const materials::MaterialTextures& m = *scene.materials.at(0).textures;
  EXPECT_EQ(m.occlusionTexture.texture, m.metallicRoughnessTexture.texture);
  EXPECT_NE(m.normalTexture.texture, m.metallicRoughnessTexture.texture);  // the same image, another sampler
  ASSERT_EQ(scene.textures.size(), 3u);
  EXPECT_EQ(scene.textures[std::size_t(m.normalTexture.texture)].sampler.magFilter, t::FACET_FILTER_NEAREST);
}

TEST_F(GltfTextures, AMaterialWithoutTexturesHasNoSlots) {
  nlohmann::json p = parts();
  p["materials"][0] = {{"pbrMetallicRoughness", {{"roughnessFactor", 0.5}}}};
  const Scene scene = loadScene(facet::testing::writeTexturedQuad(dir_, "plain", p));
  EXPECT_FALSE(scene.materials.at(0).textures.has_value());
  EXPECT_TRUE(scene.textures.empty());
}

TEST_F(GltfTextures, AMissingImageFileIsNamed) {
  nlohmann::json p = parts();
  p["images"][0]["uri"] = "nowhere.png";
  const auto file = facet::testing::writeTexturedQuad(dir_, "missing", p);
  EXPECT_THAT(
      [&] { loadScene(file); },
      ThrowsMessage<InputError>(AllOf(HasSubstr("missing.gltf"), HasSubstr("images[0]"), HasSubstr("nowhere.png"))));
}

// The backends would read different values for coordinates the mesh does
// not have, so a slot on TEXCOORD_1 of a mesh without it is refused.
TEST_F(GltfTextures, ASlotOnTexcoordsTheMeshLacksIsNamed) {
  const auto file =
      facet::testing::writeTexturedQuad(dir_, "uv1", parts({{"normalTexture", {{"index", 1}, {"texCoord", 1}}}}));
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(
                  AllOf(HasSubstr("meshes[0]: materials[0].normalTexture.texCoord is 1"), HasSubstr("TEXCOORD_1"))));
}

TEST_F(GltfTextures, ABadTextureIndexIsNamed) {
  const auto file = facet::testing::writeTexturedQuad(dir_, "index", parts({{"normalTexture", {{"index", 7}}}}));
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("materials[0].normalTexture.index"),
                                              HasSubstr("texture index 7 out of range (the file has 2 textures)"))));
}

TEST_F(GltfTextures, ANegativeTextureIndexIsNamedNotIgnored) {
  for (const char* index : {"-3", "-1", "4294967296", "1.5"}) {
    const auto file = facet::testing::writeTexturedQuad(
        dir_, "negative", parts({{"normalTexture", {{"index", nlohmann::json::parse(index)}}}}));
    EXPECT_THAT([&] { loadScene(file); },
                ThrowsMessage<InputError>(HasSubstr("materials[0].normalTexture.index: must be a whole number from 0 "
                                                    "to 2147483647 (a texture's index), is " +
                                                    nlohmann::json::parse(index).dump())));
  }
}

// tinygltf reads texCoord into an int: the file's value is checked as written,
// so no value wraps around or reaches a message as TEXCOORD_-2147483648.
TEST_F(GltfTextures, ATexCoordThatIsNotAWholeNumberInRangeIsNamedWithItsRule) {
  for (const char* texCoord : {"-2147483648", "-1", "2147483648", "4294967296", "1e20", "0.5"}) {
    const nlohmann::json value = nlohmann::json::parse(texCoord);
    const auto file = facet::testing::writeTexturedQuad(
        dir_, "texcoord", parts({{"occlusionTexture", {{"index", 0}, {"texCoord", value}}}}));
    std::string error;
    try {
      loadScene(file);
    } catch (const InputError& e) {
      error = e.what();
    }
    EXPECT_THAT(error, HasSubstr("texcoord.gltf: materials[0].occlusionTexture.texCoord: must be a whole number "
                                 "from 0 to 2147483647 (the n of the TEXCOORD_n it reads), is " +
                                 value.dump()));
    EXPECT_THAT(error, ::testing::Not(HasSubstr("TEXCOORD_-")));
  }
  const auto transform = facet::testing::writeTexturedQuad(
      dir_, "transform",
      parts({{"emissiveTexture",
              {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"texCoord", -2147483648ll}}}}}}}}));
  EXPECT_THAT([&] { loadScene(transform); },
              ThrowsMessage<InputError>(HasSubstr(
                  "materials[0].emissiveTexture.extensions.KHR_texture_transform.texCoord: must be a whole number")));
  // The author's extras are not texture infos.
  nlohmann::json p = parts({{"extras", {{"texCoord", -5}, {"index", "any"}}}});
  EXPECT_NO_THROW(loadScene(facet::testing::writeTexturedQuad(dir_, "extras", p)));
}

TEST_F(GltfTextures, AnImageOfAnUnknownFormatIsRefused) {
  std::ofstream(dir_ / "base.png") << "GIF89a, not a PNG";
  const auto file = facet::testing::writeTexturedQuad(dir_, "format", parts());
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("format.gltf: images[0] 'base.png': cannot decode the image"),
                                              HasSubstr("PNG or JPEG expected"))));
}

// A PNG that holds only its header, declaring `size` x `size` 8-bit RGBA
// texels: the decoder's header check reads no further (stb_image skips the CRC).
std::string pngHeaderOnly(std::uint32_t size) {
  std::string png = "\x89PNG\r\n\x1a\n";
  const auto word = [&](std::uint32_t w) {
    for (int shift = 24; shift >= 0; shift -= 8) png.push_back(char((w >> shift) & 0xff));
  };
  word(13);
  png += "IHDR";
  word(size);
  word(size);
  png += std::string("\x08\x06\x00\x00\x00", 5);  // 8 bits, RGBA, deflate, no filter, no interlace
  word(0);                                        // the CRC
  word(0);
  png += "IEND";
  word(0);
  return png;
}

// FACET_MEMORY_LIMIT for the scope of one test.
class MemoryLimitOf {
 public:
  explicit MemoryLimitOf(const char* mebibytes) { setenv("FACET_MEMORY_LIMIT", mebibytes, 1); }
  ~MemoryLimitOf() { unsetenv("FACET_MEMORY_LIMIT"); }
};

TEST_F(GltfTextures, AnImageBombIsRefusedFromItsHeaderNamingTheImageAndTheEstimate) {
  const MemoryLimitOf limit("64");
  std::ofstream(dir_ / "bomb.png", std::ios::binary) << pngHeaderOnly(16000);
  nlohmann::json p = parts();
  p["images"][0]["uri"] = "bomb.png";
  const auto file = facet::testing::writeTexturedQuad(dir_, "bomb", p);
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(
                  AllOf(HasSubstr("bomb.gltf: images[0] 'bomb.png': a 16000 x 16000 texture needs about "),
                        HasSubstr(" GB of memory to build and the limit is 0.1 GB (FACET_MEMORY_LIMIT)"))));
}

// A file's images are decoded one after another and all kept: each is held
// to the limit with what the ones before it keep (its samples and its
// texture's levels, 26 MB for 1024 x 1024 RGBA beside a 42 MB build).
TEST_F(GltfTextures, TheImagesOfAFileCountTogether) {
  for (const char* name : {"first.png", "second.png"})
    ASSERT_TRUE(
        facet::testing::writePng(dir_ / name, 1024, 1024, std::vector<Rgba8>(1024 * 1024, Rgba8{9, 99, 199, 255})));
  nlohmann::json p = parts();
  p["images"] = {{{"uri", "first.png"}}, {{"uri", "second.png"}}};
  const auto file = facet::testing::writeTexturedQuad(dir_, "two", p);
  {
    const MemoryLimitOf roomy("80");  // 84 MB: both
    EXPECT_EQ(loadScene(file).textures.size(), 2u);
  }
  const MemoryLimitOf limit("50");  // 52 MB: either alone, not both
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("two.gltf: images[1] 'second.png': a 1024 x 1024 texture"),
                                              HasSubstr("the images before it keep"))));
}

// Makes image `index` of writeTexturedQuad's `file` the PNG `png`, held in a
// buffer view of a second buffer (the quad's views are 0 to 2).
void putImageInABufferView(const std::filesystem::path& file, int index, const std::string& png) {
  const std::string bin = file.stem().string() + "_image.bin";
  std::ofstream(file.parent_path() / bin, std::ios::binary) << png;
  nlohmann::json document = nlohmann::json::parse(std::ifstream(file));
  document["buffers"].push_back({{"uri", bin}, {"byteLength", png.size()}});
  document["bufferViews"].push_back({{"buffer", 1}, {"byteLength", png.size()}});
  document["images"][std::size_t(index)] = {{"bufferView", 3}, {"mimeType", "image/png"}};
  std::ofstream(file) << document.dump();
}

TEST_F(GltfTextures, AnEmbeddedImageBombIsRefusedToo) {
  const MemoryLimitOf limit("64");
  const auto file = facet::testing::writeTexturedQuad(dir_, "embedded", parts());
  putImageInABufferView(file, 1, pngHeaderOnly(16000));
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("embedded.gltf: images[1]: a 16000 x 16000 texture needs"),
                                              HasSubstr("(FACET_MEMORY_LIMIT)"))));
}

std::string base64(const std::string& bytes) {
  const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t group = 0;
    for (std::size_t k = 0; k < 3; ++k) group = group << 8 | (k < n ? std::uint8_t(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) text += k <= n ? digits[(group >> (18 - 6 * k)) & 63] : '=';
  }
  return text;
}

// The three ways a glTF holds an image reach the same decoder.
TEST_F(GltfTextures, ImagesInABufferViewOrADataUriDecodeAsFromAFile) {
  const Scene fromFile = loadScene(facet::testing::writeTexturedQuad(dir_, "file", parts()));
  std::ifstream in(dir_ / "base.png", std::ios::binary);
  const std::string png{std::istreambuf_iterator<char>(in), {}};
  const auto view = facet::testing::writeTexturedQuad(dir_, "view", parts());
  putImageInABufferView(view, 0, png);
  nlohmann::json p = parts();
  p["images"][0] = {{"uri", "data:image/png;base64," + base64(png)}};
  const auto dataUri = facet::testing::writeTexturedQuad(dir_, "data", p);
  for (const auto& file : {view, dataUri}) {
    const Scene scene = loadScene(file);
    ASSERT_EQ(scene.textures.size(), fromFile.textures.size()) << file;
    for (std::size_t t = 0; t < scene.textures.size(); ++t)
      EXPECT_EQ(scene.textures[t].levels[0].texels, fromFile.textures[t].levels[0].texels) << file;
  }
}

TEST_F(GltfTextures, AnImageLargerThanTheSizeLimitIsRefusedFromItsHeader) {
  std::string grey = pngHeaderOnly(20000);  // grey: stb_image itself refuses more than 2^30 bytes
  grey[25] = 0;
  std::ofstream(dir_ / "wide.png", std::ios::binary) << grey;
  nlohmann::json p = parts();
  p["images"][0]["uri"] = "wide.png";
  const auto file = facet::testing::writeTexturedQuad(dir_, "wide", p);
  EXPECT_THAT([&] { loadScene(file); }, ThrowsMessage<InputError>(HasSubstr(
                                            "wide.gltf: images[0] 'wide.png': an image must be at most 16384 x 16384, "
                                            "it is 20000 x 20000")));
}

// Opening a FIFO for reading blocks until a writer comes: the refusal must
// come from its kind, before any open (a hang fails the test by its timeout).
TEST_F(GltfTextures, AFifoOrAFolderAsAnImageIsRefusedAtOnce) {
  ASSERT_EQ(mkfifo((dir_ / "fifo.png").c_str(), 0600), 0);
  std::filesystem::create_directory(dir_ / "folder.png");
  for (const auto& [name, rule] : {std::pair{"fifo.png", "it is a FIFO, socket or device, not a regular file"},
                                   std::pair{"folder.png", "it is a folder, not a file"}}) {
    nlohmann::json p = parts();
    p["images"][1]["uri"] = name;
    const auto file = facet::testing::writeTexturedQuad(dir_, "kind", p);
    EXPECT_THAT([&] { loadScene(file); },
                ThrowsMessage<InputError>(AllOf(HasSubstr((dir_ / name).string() + ": cannot open a file that "),
                                                HasSubstr("kind.gltf names: "), HasSubstr(rule))));
  }
}

TEST_F(GltfTextures, AFifoAsABufferIsRefusedAtOnce) {
  ASSERT_EQ(mkfifo((dir_ / "fifo.bin").c_str(), 0600), 0);
  const auto file = facet::testing::writeTexturedQuad(dir_, "buffer", parts());
  nlohmann::json document = nlohmann::json::parse(std::ifstream(file));
  document["buffers"][0]["uri"] = "fifo.bin";
  std::ofstream(file) << document.dump();
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("fifo.bin: cannot open a file that "), HasSubstr("FIFO"))));
}

TEST_F(GltfTextures, SixteenBitImagesKeepTheirPrecision) {
  // 1 x 1 grey, 16 bits: 0x4000 + 1, which 8 bits cannot hold.
  std::string png = pngHeaderOnly(1);
  png.replace(24, 2, std::string("\x10\x00", 2));  // 16 bits, grey
  const std::string scanline("\x00\x40\x01", 3);   // no filter, then the sample (big-endian)
  std::string idat = std::string("\x78\x01\x01\x03\x00\xfc\xff", 7) + scanline + std::string(4, '\0');  // stored
  std::string chunk = std::string(3, '\0') + std::string(1, char(idat.size())) + "IDAT" + idat + std::string(4, '\0');
  png.insert(png.size() - 12, chunk);  // before IEND
  std::ofstream(dir_ / "wide.png", std::ios::binary) << png;
  nlohmann::json p = parts();
  p["images"][1]["uri"] = "wide.png";
  const Scene scene = loadScene(facet::testing::writeTexturedQuad(dir_, "wide", p));
  const materials::MaterialTextures& m = *scene.materials.at(0).textures;
  const Texture& data = scene.textures.at(std::size_t(m.metallicRoughnessTexture.texture));
  EXPECT_EQ(data.levels[0].texels[0], glm::vec4(glm::vec3(float(0x4001) / 65535.0f), 1.0f));
}

TEST_F(GltfTextures, AnUnknownWrapModeIsNamed) {
  nlohmann::json p = parts();
  p["samplers"][0]["wrapS"] = 1234;
  const auto file = facet::testing::writeTexturedQuad(dir_, "wrap", p);
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("samplers[0].wrapS"), HasSubstr("unknown wrap mode 1234"))));
}

// Past 1e6 the GPU's float texture coordinates part from the CPU's double
// (a normal scale of 1e20 overflows the normal map's frame in float).
TEST_F(GltfTextures, ATextureScaleBeyondAMillionIsRefused) {
  const auto transform = [](const nlohmann::json& scale) {
    return nlohmann::json{{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", scale}}}}}};
  };
  for (const double scale : {1e30, -1e7, 1e300}) {
    const auto file =
        facet::testing::writeTexturedQuad(dir_, "scale", parts({{"emissiveTexture", transform({1.0, scale})}}));
    EXPECT_THAT([&] { loadScene(file); },
                ThrowsMessage<InputError>(HasSubstr(
                    "scale.gltf: materials[0].emissiveTexture.extensions.KHR_texture_transform.scale[1]: must be "
                    "within -1e6 to 1e6 (the GPU computes texture coordinates in float), is " +
                    nlohmann::json(scale).dump())));
    const auto normal =
        facet::testing::writeTexturedQuad(dir_, "normal", parts({{"normalTexture", {{"index", 1}, {"scale", scale}}}}));
    EXPECT_THAT([&] { loadScene(normal); },
                ThrowsMessage<InputError>(HasSubstr("normal.gltf: materials[0].normalTexture.scale: must be within")));
    const nlohmann::json coat = {{"clearcoatFactor", 1.0}, {"clearcoatNormalTexture", {{"index", 1}, {"scale", scale}}}};
    const auto coated = facet::testing::writeTexturedQuad(
        dir_, "coat", parts({{"extensions", {{"KHR_materials_clearcoat", coat}}}}));
    EXPECT_THAT([&] { loadScene(coated); },
                ThrowsMessage<InputError>(HasSubstr(
                    "coat.gltf: materials[0].extensions.KHR_materials_clearcoat.clearcoatNormalTexture.scale: must be "
                    "within")));
  }
  const Scene bound = loadScene(facet::testing::writeTexturedQuad(
      dir_, "bound",
      parts({{"emissiveTexture", transform({1e6, -1e6})}, {"normalTexture", {{"index", 1}, {"scale", -1e6}}}})));
  EXPECT_EQ(bound.materials.at(0).textures->emissiveTexture.scale, glm::dvec2(1e6, -1e6));
  EXPECT_EQ(bound.materials.at(0).textures->normalScale, -1e6);
}

TEST_F(GltfTextures, ABadTransformIsNamed) {
  const auto file = facet::testing::writeTexturedQuad(
      dir_, "transform",
      parts({{"emissiveTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {1}}}}}}}}}));
  EXPECT_THAT([&] { loadScene(file); }, ThrowsMessage<InputError>(HasSubstr(
                                            "materials[0].emissiveTexture.extensions.KHR_texture_transform.scale: "
                                            "must be an array of 2 numbers")));
}

}  // namespace
}  // namespace facet::scene
