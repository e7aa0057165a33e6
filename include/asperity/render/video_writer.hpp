// Writes frames to a video through the `ffmpeg` program (Debian's ffmpeg package): raw RGB
// frames are piped to `ffmpeg -f rawvideo`, which encodes H.264 (yuv420p, even-padded).
#pragma once

#include <cstdio>
#include <memory>
#include <string>

#include "asperity/render/renderer.hpp"

namespace asperity {
class AtomicOutput;  // asperity/math/atomic_file.hpp
}  // namespace asperity

namespace asperity::render {

// Full path of an executable found on PATH, or "" when there is none.
std::string findExecutable(const std::string& name);

class VideoWriter {
 public:
  // Starts ffmpeg writing `path` at `fps` (into PATH.tmp, renamed by finish(): a killed render
  // leaves no cut video under the final name). Throws asperity::Error when ffmpeg is not on PATH
  // (naming the package) or cannot be started.
  VideoWriter(const std::string& path, int width, int height, double fps);
  // Closes the pipe if finish() was not called (errors ignored).
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // Appends one frame of the writer's size. Throws asperity::Error when ffmpeg stopped.
  void write(const Image& frame);
  // Waits for ffmpeg; throws asperity::Error naming the file when it failed.
  void finish();

 private:
  std::string path_;
  std::unique_ptr<AtomicOutput> output_;  // ffmpeg writes its temporary; finish() renames it
  int width_ = 0;
  int height_ = 0;
  FILE* pipe_ = nullptr;
};

}  // namespace asperity::render
