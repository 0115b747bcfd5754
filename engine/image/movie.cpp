#include "engine/image/movie.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "engine/image/child_process.h"
#include "engine/image/image_io.h"

namespace facet {

namespace fs = std::filesystem;

std::optional<MovieFormat> movieFormat(const fs::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".mp4") return MovieFormat::Mp4;
  if (extension == ".gif") return MovieFormat::Gif;
  return std::nullopt;
}

fs::path framePath(const fs::path& folder, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", frame);
  return folder / name;
}

std::vector<std::string> ffmpegArguments(const fs::path& ffmpeg, const fs::path& folder, int frames, double fps,
                                         const fs::path& output, MovieFormat format) {
  std::string pattern;  // image2's pattern: "%%" is a literal '%'
  for (char c : fs::absolute(folder).string()) pattern += c == '%' ? std::string("%%") : std::string(1, c);
  pattern += "/frame_%05d.png";
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", fps);
  std::vector<std::string> a = {ffmpeg.string(),
                                "-nostdin",
                                "-hide_banner",
                                "-loglevel",
                                "error",
                                "-y",
                                "-framerate",
                                rate,
                                "-start_number",
                                "0",
                                "-i",
                                pattern,
                                "-frames:v",
                                std::to_string(frames)};
  if (format == MovieFormat::Mp4) {
    // H.264 in 4:2:0 needs even sizes; yuv420p is what players expect.
    for (const char* s : {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-movflags",
                          "+faststart", "-f", "mp4"})
      a.emplace_back(s);
  } else {
    // One palette for the whole movie, made from its own frames.
    for (const char* s :
         {"-filter_complex", "split[a][b];[a]palettegen[p];[b][p]paletteuse", "-loop", "0", "-f", "gif"})
      a.emplace_back(s);
  }
  a.push_back(fs::absolute(output).string());  // absolute: never read as an option
  return a;
}

void writeMovie(const fs::path& folder, int frames, double fps, const fs::path& output, const std::string& path) {
  const std::optional<MovieFormat> format = movieFormat(output);
  if (!format) throw OutputError("--movie '" + output.string() + "': expected an .mp4 or .gif file");
  const std::optional<fs::path> ffmpeg = findOnPath("ffmpeg", path);
  if (!ffmpeg) throw OutputError("--movie '" + output.string() + "': " + kFfmpegMissing);
  writeAtomically(output, [&](const fs::path& temporary) {
    try {
      runChild({ffmpegArguments(*ffmpeg, folder, frames, fps, temporary, *format), std::nullopt, kFfmpegTimeLimit});
    } catch (const std::runtime_error& e) {
      throw OutputError("--movie '" + output.string() + "': " + e.what());
    }
    if (!fs::is_regular_file(temporary) || fs::file_size(temporary) == 0)
      throw OutputError("--movie '" + output.string() + "': ffmpeg wrote no movie");
  });
}

}  // namespace facet
