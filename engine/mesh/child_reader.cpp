#include "engine/mesh/child_reader.hpp"

#include <fmt/format.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "engine/mesh/gmsh_mesher.hpp"  // MeshError
#include "engine/mesh/mesh_cache.hpp"

namespace ccm {
namespace {

using Clock = std::chrono::steady_clock;

// Writes all of `bytes` to the descriptor (a pipe); false when it cannot.
bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// Everything the child writes until it closes the pipe; nothing when the deadline passes first.
std::optional<std::string> read_until(int fd, Clock::time_point deadline) {
  std::string bytes;
  char buffer[65536];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count())));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) return std::nullopt;
    if (ready < 0) return bytes;
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return bytes;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
}

// The child's side: the mesh as "M" + bytes, a MeshError as "E" + message, another exception as
// "X" + message. Never returns.
[[noreturn]] void answer(int fd, const std::function<TetMesh()>& read) {
  // A crash ends the child by its signal, whatever handler the parent installed (a test
  // framework's would report a failure from the child and print its own summary).
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(sig, SIG_DFL);
  std::string reply;
  try {
    // (appended, not "M" + bytes: GCC 12 warns of a false memcpy overflow in operator+)
    reply = "M";
    reply += mesh_bytes(read());
  } catch (const MeshError& e) {
    reply = std::string("E") + e.what();
  } catch (const std::exception& e) {
    reply = std::string("X") + e.what();
  }
  _exit(write_all(fd, reply) ? 0 : 1);
}

struct Attempt {
  std::optional<std::string> reply;  // none: the deadline passed and the child was killed
  int status = 0;                    // the child's, from waitpid
};

Attempt attempt(const std::string& where, const ChildReadSettings& settings,
                const std::function<TetMesh()>& read) {
  int fds[2];
  if (::pipe(fds) != 0) throw MeshError(fmt::format("{}: cannot make a pipe to read it", where));
  std::fflush(nullptr);
  pid_t pid = -1;
  if (settings.fork_lock) {
    const std::lock_guard<std::mutex> lock(*settings.fork_lock);
    pid = ::fork();
  } else {
    pid = ::fork();
  }
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw MeshError(fmt::format("{}: cannot start a process to read it", where));
  }
  if (pid == 0) {
    ::close(fds[0]);
    answer(fds[1], read);
  }
  ::close(fds[1]);
  Attempt a;
  a.reply = read_until(fds[0], Clock::now() + settings.deadline);
  ::close(fds[0]);
  if (!a.reply) ::kill(pid, SIGKILL);
  while (::waitpid(pid, &a.status, 0) < 0 && errno == EINTR) {
  }
  return a;
}

}  // namespace

std::chrono::milliseconds reader_deadline(std::uintmax_t bytes) {
  return std::chrono::milliseconds(5000 + bytes / 1000);  // 5 s + 1 ms per kB
}

TetMesh read_in_child(const std::string& where, const ChildReadSettings& settings,
                      const std::function<TetMesh()>& read) {
  Attempt a = attempt(where, settings, read);
  if (!a.reply) a = attempt(where, settings, read);  // once more: a stuck child is rare
  if (!a.reply)
    throw MeshError(fmt::format(
        "{}: the process reading it did not finish within {:.1f} s, twice; a file this size "
        "reads in well under that",
        where, 1e-3 * static_cast<double>(settings.deadline.count())));
  if (WIFSIGNALED(a.status))
    throw MeshError(fmt::format(
        "{}: Gmsh's reader crashed on the file (signal {}, {}): it is malformed in a way Gmsh "
        "does not check; write it again from the tool that made it",
        where, WTERMSIG(a.status), strsignal(WTERMSIG(a.status))));
  const std::string& reply = *a.reply;
  TetMesh mesh;
  if (!reply.empty() && reply[0] == 'M' && read_mesh_bytes(reply.substr(1), mesh)) return mesh;
  if (!reply.empty() && reply[0] == 'E') throw MeshError(reply.substr(1));
  if (!reply.empty() && reply[0] == 'X') throw std::runtime_error(reply.substr(1));
  throw MeshError(fmt::format("{}: the process reading it ended without an answer (exit {})", where,
                              WIFEXITED(a.status) ? WEXITSTATUS(a.status) : -1));
}

}  // namespace ccm
