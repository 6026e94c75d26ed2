// A video from numbered images, made by the `ffmpeg` program (Debian package ffmpeg).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace sph::render {

// ffmpeg is missing or failed; the message says which, with ffmpeg's last words.
class VideoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Encodes `imagePattern` (printf style, e.g. DIR/images/frame_%05d.png, numbered from 0) as an
// H.264 MP4 in yuv420p (what players and browsers accept; odd sizes are padded to even) at
// `fps` frames per second. The images are left as they are. Throws VideoError.
void encodeVideo(const std::string& imagePattern, double fps, const std::filesystem::path& video);

}  // namespace sph::render
