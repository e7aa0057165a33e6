// ffmpeg pipe for MP4 output.
#include "asperity/render/video_writer.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <sstream>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"

namespace asperity::render {
namespace {

// Single quotes for /bin/sh, with embedded quotes escaped.
std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::string findExecutable(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

VideoWriter::VideoWriter(const std::string& path, int width, int height, double fps)
    : path_(path), output_(std::make_unique<AtomicOutput>(path)), width_(width), height_(height) {
  const std::string ffmpeg = findExecutable("ffmpeg");
  if (ffmpeg.empty())
    throw Error(path +
                ": cannot write a video: ffmpeg is not on PATH (install Debian's ffmpeg "
                "package, or write PNG frames into a folder: --out DIR/)");
  // Raw RGB frames in, H.264 out; odd sizes are padded to even for yuv420p.
  std::ostringstream command;
  command << shellQuote(ffmpeg) << " -y -loglevel error -f rawvideo -pix_fmt rgb24 -s " << width
          << "x" << height << " -r " << fps
          << " -i - -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -c:v libx264 -preset medium -crf 18"
          << " -pix_fmt yuv420p -movflags +faststart -f mp4 "
          << shellQuote(output_->temporaryPath());
  // A closed pipe must surface as an error from write(), not kill the process.
  std::signal(SIGPIPE, SIG_IGN);
  pipe_ = popen(command.str().c_str(), "w");
  if (pipe_ == nullptr) throw Error(path + ": cannot start ffmpeg");
}

VideoWriter::~VideoWriter() {
  if (pipe_ != nullptr) pclose(pipe_);
}

void VideoWriter::write(const Image& frame) {
  if (pipe_ == nullptr) throw Error(path_ + ": video already finished");
  if (frame.width != width_ || frame.height != height_)
    throw Error(path_ + ": frame size differs from the video's");
  if (std::fwrite(frame.rgb.data(), 1, frame.rgb.size(), pipe_) != frame.rgb.size())
    throw Error(path_ + ": ffmpeg stopped accepting frames (see its message above)");
}

void VideoWriter::finish() {
  if (pipe_ == nullptr) return;
  const int status = pclose(pipe_);
  pipe_ = nullptr;
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error(path_ + ": ffmpeg failed to write the video (exit status " +
                std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  // Whole: under its name now (until then ffmpeg wrote a temporary beside it).
  output_->commit();
}

}  // namespace asperity::render
