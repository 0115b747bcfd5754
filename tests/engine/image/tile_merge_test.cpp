// facet merge's engine: tiles of one render back into the whole image, bit
// for bit, and every way a set of tiles can fail to be one render refused
// before anything is written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/image/exr_file.h"
#include "engine/image/tile_merge.h"
#include "tests/support/image_windows.h"
#include "tests/support/random_image.h"
#include "tests/support/temp_dir.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 41, kHeight = 150;  // taller than the merge's band of rows

// The window's pixels of `whole`, as a render of that crop returns them.
Image cropOf(const Image& whole, const PixelRect& window) {
  Image crop(window.width(), window.height());
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x) {
      const std::size_t c = crop.index(x, y), w = whole.index(window.x0 + x, window.y0 + y);
      crop.beauty[c] = whole.beauty[w];
      crop.depth[c] = whole.depth[w];
      crop.position[c] = whole.position[w];
      crop.geometricNormal[c] = whole.geometricNormal[w];
      crop.shadingNormal[c] = whole.shadingNormal[w];
      crop.patchId[c] = whole.patchId[w];
      crop.faceId[c] = whole.faceId[w];
      crop.uv[c] = whole.uv[w];
      crop.texcoord[c] = whole.texcoord[w];
    }
  return crop;
}

class TileMerge : public testing::TempDirTest {
 protected:
  const Image whole_ = testing::randomImage(kWidth, kHeight);

  fs::path writeTile(const std::string& name, const PixelRect& window, const std::string& digest = "d1") {
    const Image crop = cropOf(whole_, window);
    writeExr(dir_ / name, crop, {ExrPlacement{window, kWidth, kHeight, digest}});
    return dir_ / name;
  }

  std::string mergeError(const std::vector<fs::path>& tiles) {
    try {
      mergeTiles(tiles, {dir_ / "merged.exr", dir_ / "merged.png"});
    } catch (const std::invalid_argument& e) {
      EXPECT_FALSE(fs::exists(dir_ / "merged.exr"));
      EXPECT_FALSE(fs::exists(dir_ / "merged.png"));
      return e.what();
    }
    return "(merged)";
  }
};

TEST_F(TileMerge, TilesOfAnyShapeMergeIntoTheWholeImageBitForBit) {
  // Rows 0..70 in bands, 70..150 in three columns of unequal width.
  const std::vector<fs::path> tiles = {
      writeTile("a.exr", tileRows(kWidth, 70, 0, 2)), writeTile("b.exr", tileRows(kWidth, 70, 1, 2)),
      writeTile("c.exr", {0, 70, 10, kHeight}),       writeTile("d.exr", {10, 70, 11, kHeight}),
      writeTile("e.exr", {11, 70, kWidth, kHeight}),
  };
  mergeTiles(tiles, {dir_ / "merged.exr", dir_ / "merged.png"});
  const Image merged = readExr(dir_ / "merged.exr");
  EXPECT_THAT(testing::pixelsThatDiffer(whole_, merged, PixelRect::whole(kWidth, kHeight)), ::testing::IsEmpty());
  EXPECT_GT(fs::file_size(dir_ / "merged.png"), 0u);
}

TEST_F(TileMerge, AGapIsRefusedAndNothingIsWritten) {
  const std::string error = mergeError(
      {writeTile("a.exr", tileRows(kWidth, kHeight, 0, 3)), writeTile("c.exr", tileRows(kWidth, kHeight, 2, 3))});
  EXPECT_THAT(error, ::testing::HasSubstr("pixel (0, 50) is in no tile"));
}

TEST_F(TileMerge, AGapInsideARowIsRefused) {
  const std::string error =
      mergeError({writeTile("a.exr", {0, 0, 20, kHeight}), writeTile("b.exr", {21, 0, kWidth, kHeight})});
  EXPECT_THAT(error, ::testing::HasSubstr("pixel (20, 0) is in no tile"));
}

TEST_F(TileMerge, AnOverlapIsRefused) {
  const std::string error =
      mergeError({writeTile("a.exr", {0, 0, kWidth, 80}), writeTile("b.exr", {0, 79, kWidth, kHeight})});
  EXPECT_THAT(error, ::testing::MatchesRegex(".*b.exr: data window 0,79,41,150: overlaps .*a.exr's 0,0,41,80"));
}

TEST_F(TileMerge, TilesOfAnotherRenderAreRefused) {
  const std::string error = mergeError(
      {writeTile("a.exr", tileRows(kWidth, kHeight, 0, 2)), writeTile("b.exr", tileRows(kWidth, kHeight, 1, 2), "d2")});
  EXPECT_THAT(error, ::testing::HasSubstr("b.exr: facetSettingsDigest: differs from"));
}

TEST_F(TileMerge, AFileWithoutADigestIsRefused) {
  writeExr(dir_ / "plain.exr", whole_);
  EXPECT_THAT(mergeError({dir_ / "plain.exr"}), ::testing::HasSubstr("plain.exr: header: no facetSettingsDigest"));
}

TEST_F(TileMerge, OtherChannelsAreRefused) {
  const fs::path a = writeTile("a.exr", tileRows(kWidth, kHeight, 0, 2));
  // The second half with its beauty alone.
  const PixelRect window = tileRows(kWidth, kHeight, 1, 2);
  Imf::Header header(Imath::Box2i({0, 0}, {kWidth - 1, kHeight - 1}),
                     Imath::Box2i({window.x0, window.y0}, {window.x1 - 1, window.y1 - 1}));
  header.insert(kSettingsDigestAttribute, Imf::StringAttribute("d1"));
  std::vector<float> red(window.pixelCount());
  header.channels().insert("R", Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer frame;
  frame.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(red.data() - window.y0 * kWidth), sizeof(float),
                               sizeof(float) * kWidth));
  {
    Imf::OutputFile file((dir_ / "b.exr").c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(window.height());
  }
  EXPECT_THAT(mergeError({a, dir_ / "b.exr"}), ::testing::HasSubstr("b.exr: channels 'R' differs from"));
}

TEST_F(TileMerge, ANonExrFileIsRefused) {
  std::ofstream(dir_ / "junk.exr") << "not an image";
  EXPECT_THAT(mergeError({dir_ / "junk.exr"}), ::testing::HasSubstr("junk.exr: cannot read EXR"));
}

TEST_F(TileMerge, AFailedMergeKeepsTheOldOutput) {
  std::ofstream(dir_ / "merged.exr") << "an earlier merge";
  EXPECT_THROW(mergeTiles({writeTile("a.exr", tileRows(kWidth, kHeight, 0, 2))}, {dir_ / "merged.exr"}),
               std::invalid_argument);
  std::ifstream kept(dir_ / "merged.exr");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "an earlier merge");
}

TEST_F(TileMerge, TheMergeKeepsTheHeaderAndTheIdLayersOfAHalfBeauty) {
  ExrOptions options;
  options.metadata = {ExrCamera{}, {"facet 1.2.3", "backend=cpu", {}, {}}, ExrNames{{"ball"}, {0}, {0}, {"gold"}}};
  options.halfBeauty = true;
  std::vector<fs::path> tiles;
  for (int i = 0; i < 2; ++i) {
    options.placement = ExrPlacement{tileRows(kWidth, kHeight, i, 2), kWidth, kHeight, "d1"};
    tiles.push_back(dir_ / ("tile" + std::to_string(i) + ".exr"));
    writeExr(tiles.back(), cropOf(whole_, options.placement->dataWindow), options);
  }
  options.placement.reset();
  writeExr(dir_ / "whole.exr", whole_, options);
  mergeTiles(tiles, {dir_ / "merged.exr", dir_ / "merged.png"});

  Imf::InputFile merged((dir_ / "merged.exr").c_str()), whole((dir_ / "whole.exr").c_str());
  const Imf::Header &m = merged.header(), &w = whole.header();
  EXPECT_EQ(m.channels().findChannel("R")->type, Imf::HALF);
  EXPECT_NE(m.channels().findChannel("CryptoObject00.R"), nullptr);
  EXPECT_NE(m.channels().findChannel("objectId"), nullptr);
  EXPECT_EQ(Imf::worldToNDC(m), Imf::worldToNDC(w));
  for (auto a = w.begin(); a != w.end(); ++a) {
    if (std::string(a.attribute().typeName()) == "string") {
      EXPECT_EQ(m.typedAttribute<Imf::StringAttribute>(a.name()).value(),
                w.typedAttribute<Imf::StringAttribute>(a.name()).value())
          << a.name();
    }
  }
  const Image back = readExr(dir_ / "merged.exr"), expected = readExr(dir_ / "whole.exr");
  EXPECT_THAT(testing::pixelsThatDiffer(expected, back, PixelRect::whole(kWidth, kHeight)), ::testing::IsEmpty());
  EXPECT_GT(fs::file_size(dir_ / "merged.png"), 0u);
}

}  // namespace
}  // namespace facet
