// ffmpeg's arguments are an argv built from paths, never shell text; a
// missing or failing ffmpeg leaves no movie behind.
#include "engine/image/movie.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "engine/image/child_process.h"
#include "engine/image/image_io.h"
#include "tests/support/temp_dir.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

class Movie : public facet::testing::TempDirTest {
 protected:
  // An executable `ffmpeg` in its own folder running `body` (sh).
  fs::path fakeFfmpeg(const std::string& body) {
    const fs::path bin = dir_ / "bin";
    fs::create_directories(bin);
    std::ofstream(bin / "ffmpeg") << "#!/bin/sh\n" << body << "\n";
    ::chmod((bin / "ffmpeg").c_str(), 0755);
    return bin;
  }
};

std::string after(const std::vector<std::string>& a, const std::string& flag) {
  const auto at = std::find(a.begin(), a.end(), flag);
  return at == a.end() || at + 1 == a.end() ? std::string("(none)") : *(at + 1);
}

TEST_F(Movie, ArgumentsNameTheFramesInOrderAndTheOutputLast) {
  const fs::path frames = dir_ / "frames";
  const fs::path out = dir_ / "it's \"quoted\" $(touch x).mp4";
  const std::vector<std::string> a = ffmpegArguments("/usr/bin/ffmpeg", frames, 36, 24, out, MovieFormat::Mp4);
  EXPECT_EQ(a.front(), "/usr/bin/ffmpeg");
  EXPECT_EQ(a.back(), out.string()) << "the name, quotes and all, is one argument";
  EXPECT_EQ(after(a, "-i"), (frames / "frame_%05d.png").string());
  EXPECT_EQ(after(a, "-start_number"), "0");
  EXPECT_EQ(after(a, "-frames:v"), "36");
  EXPECT_EQ(after(a, "-framerate"), "24");
  EXPECT_EQ(after(a, "-f"), "mp4") << "the temporary's name has no extension to go by";
  EXPECT_EQ(after(a, "-pix_fmt"), "yuv420p");
  EXPECT_NE(std::find(a.begin(), a.end(), "-nostdin"), a.end());
  const std::vector<std::string> gif = ffmpegArguments("ffmpeg", frames, 4, 12.5, out, MovieFormat::Gif);
  EXPECT_EQ(after(gif, "-f"), "gif");
  EXPECT_EQ(after(gif, "-framerate"), "12.5");
  EXPECT_EQ(framePath(frames, 7), frames / "frame_00007.png");
}

TEST_F(Movie, APercentInTheFolderIsNotAPattern) {
  const std::vector<std::string> a =
      ffmpegArguments("ffmpeg", dir_ / "100%d", 2, 24, dir_ / "out.gif", MovieFormat::Gif);
  EXPECT_EQ(after(a, "-i"), (dir_ / "100%%d" / "frame_%05d.png").string());
}

TEST_F(Movie, RelativeOutputsBecomeAbsoluteSoNoneReadsAsAnOption) {
  const fs::path before = fs::current_path();
  fs::current_path(dir_);
  const std::vector<std::string> a = ffmpegArguments("ffmpeg", "f", 2, 24, "-y.mp4", MovieFormat::Mp4);
  fs::current_path(before);
  EXPECT_EQ(a.back(), (dir_ / "-y.mp4").string());
}

TEST_F(Movie, FormatsByExtension) {
  EXPECT_EQ(movieFormat("a.MP4"), MovieFormat::Mp4);
  EXPECT_EQ(movieFormat("a.gif"), MovieFormat::Gif);
  EXPECT_FALSE(movieFormat("a.mov"));
  EXPECT_FALSE(movieFormat("mp4"));
}

TEST_F(Movie, FindsAnExecutableOnThePathOnly) {
  const fs::path bin = fakeFfmpeg("exit 0");
  std::ofstream(dir_ / "ffmpeg") << "not executable";
  EXPECT_EQ(findOnPath("ffmpeg", (dir_ / "nothing").string() + ":" + bin.string()), bin / "ffmpeg");
  EXPECT_FALSE(findOnPath("ffmpeg", dir_.string()));
  EXPECT_FALSE(findOnPath("ffmpeg", ""));
}

TEST_F(Movie, MissingFfmpegIsAnOutputErrorAndWritesNothing) {
  const fs::path out = dir_ / "turn.mp4";
  try {
    writeMovie(dir_, 2, 24, out, (dir_ / "empty").string());
    FAIL() << "no ffmpeg, no movie";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("apt-get install ffmpeg"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Movie, AFailingFfmpegLeavesNoMovieAndKeepsAnOldOne) {
  // Writes its last argument, then fails, as an ffmpeg that runs out of disk.
  const fs::path bin = fakeFfmpeg("for last; do :; done; echo partial > \"$last\"; exit 3");
  const fs::path out = dir_ / "turn.gif";
  EXPECT_THROW(writeMovie(dir_, 2, 24, out, bin.string()), OutputError);
  EXPECT_FALSE(fs::exists(out));
  std::ofstream(out) << "old";
  EXPECT_THROW(writeMovie(dir_, 2, 24, out, bin.string()), OutputError);
  std::ifstream kept(out);
  std::string text;
  kept >> text;
  EXPECT_EQ(text, "old");
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename().string().find("turn.gif.tmp-"), std::string::npos) << "a temporary is left";
}

TEST_F(Movie, ASucceedingFfmpegPutsItsFileInPlace) {
  const fs::path bin = fakeFfmpeg("for last; do :; done; echo movie > \"$last\"");
  const fs::path out = dir_ / "turn.mp4";
  writeMovie(dir_, 2, 24, out, bin.string());
  std::ifstream written(out);
  std::string text;
  written >> text;
  EXPECT_EQ(text, "movie");
}

}  // namespace
}  // namespace facet
