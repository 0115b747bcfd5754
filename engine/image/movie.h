// A movie (MP4 or GIF) of numbered PNG frames, made by Debian's ffmpeg run
// as a separate process found on PATH (docs/preview-stage.md, "Turntables").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace facet {

enum class MovieFormat { Mp4, Gif };

// The format `path`'s extension names (.mp4 or .gif, any case); none
// otherwise.
std::optional<MovieFormat> movieFormat(const std::filesystem::path& path);

// What to do where ffmpeg is missing, for the error that says so.
inline constexpr const char* kFfmpegMissing = "ffmpeg is not on PATH; install it (Debian: apt-get install ffmpeg)";

// What ffmpeg may take to make a movie before it is ended: far beyond a
// turntable's few thousand frames (engine/image/child_process.h).
inline constexpr double kFfmpegTimeLimit = 600;

// The numbered frames: `folder`/frame_00000.png, frame_00001.png, ...
std::filesystem::path framePath(const std::filesystem::path& folder, int frame);

// ffmpeg's argument list, argv[0] first: `frames` frames of `folder`
// (framePath's names, from 0) at `fps` to `output` in `format`. Each path is
// one argument, never shell text, and the frames' folder reaches ffmpeg's
// pattern with any '%' doubled, so no name is read as a pattern.
std::vector<std::string> ffmpegArguments(const std::filesystem::path& ffmpeg, const std::filesystem::path& folder,
                                         int frames, double fps, const std::filesystem::path& output,
                                         MovieFormat format);

// The movie of `frames` frames in `folder` written to `output`, through a
// temporary file renamed into place: where ffmpeg fails, no `output` is left
// and an existing one is untouched. Throws OutputError (engine/image/image_io.h)
// where ffmpeg is missing from `path` or fails.
void writeMovie(const std::filesystem::path& folder, int frames, double fps, const std::filesystem::path& output,
                const std::string& path);

}  // namespace facet
