#include "video.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

extern char** environ;

namespace sph::render {

namespace fs = std::filesystem;

namespace {

std::string lastLines(const fs::path& log, std::size_t maxChars) {
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s.size() > maxChars ? "..." + s.substr(s.size() - maxChars) : s;
}

}  // namespace

void encodeVideo(const std::string& imagePattern, double fps, const fs::path& video) {
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", fps);
  fs::path partial = video;
  partial += ".part.mp4";  // ffmpeg picks the container from the extension
  const fs::path log = video.string() + ".log";
  std::vector<std::string> args = {
      "ffmpeg", "-y", "-loglevel", "error", "-framerate", rate, "-i", imagePattern,
      // H.264 in yuv420p needs even sizes: pad by one pixel.
      "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf",
      "20", "-movflags", "+faststart", partial.string()};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int spawnError = posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawnError != 0) {
    std::error_code ignored;
    fs::remove(log, ignored);
    throw VideoError(
        std::string("cannot run ffmpeg: ") + std::strerror(spawnError) +
        (spawnError == ENOENT ? " (not on PATH; Debian: apt-get install ffmpeg)" : ""));
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::error_code ignored;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string said = lastLines(log, 600);
    fs::remove(partial, ignored);
    fs::remove(log, ignored);
    throw VideoError("ffmpeg failed (" +
                     (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                        : std::string("killed by a signal")) +
                     ")" + (said.empty() ? "" : ": " + said));
  }
  fs::remove(log, ignored);
  std::error_code renameError;
  fs::rename(partial, video, renameError);
  if (renameError)
    throw VideoError("cannot rename onto '" + video.string() + "': " + renameError.message());
}

}  // namespace sph::render
