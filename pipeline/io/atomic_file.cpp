#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <optional>
#include <regex>

namespace asvgf::render {
namespace {

enum class Op { Write, Flush, Sync, Close, Rename };
constexpr std::array<const char*, 5> kOpNames = {"write", "flush", "sync", "close", "rename"};

struct FaultPlan {
  std::optional<Op> op;  // nullopt: count only
  unsigned nth = 0;
  bool report = false;
};

FaultPlan parse_fault(const char* value) {
  FaultPlan plan;
  if (!value || !*value) return plan;
  const std::string v = value;
  if (v == "count") {
    plan.report = true;
    return plan;
  }
  const auto colon = v.find(':');
  if (colon != std::string::npos) {
    const std::string op = v.substr(0, colon), n = v.substr(colon + 1);
    for (std::size_t i = 0; i < kOpNames.size(); ++i)
      if (op == kOpNames[i] && !n.empty() && n.size() < 9 && n.find_first_not_of("0123456789") == std::string::npos &&
          std::stoul(n) > 0) {
        plan.op = Op(i);
        plan.nth = unsigned(std::stoul(n));
        return plan;
      }
  }
  throw std::invalid_argument("ASVGF_FILE_FAULT: '" + v +
                              "' is not 'count' or '<op>:<n>' (op: write, flush, sync, close, rename; n >= 1)");
}

struct Faults {
  FaultPlan plan;
  std::array<std::atomic<unsigned>, 5> counts{};
  Faults() {
    try {
      plan = parse_fault(std::getenv("ASVGF_FILE_FAULT"));
    } catch (const std::invalid_argument&) {
      plan = {};  // check_file_fault_environment reports it
    }
    if (plan.report) std::atexit(report);
  }
  static void report();
};

Faults& faults() {
  static Faults f;
  return f;
}

void Faults::report() {
  auto& f = faults();
  std::string line = "file fault counts:";
  for (std::size_t i = 0; i < kOpNames.size(); ++i)
    line += std::string(i ? ", " : " ") + kOpNames[i] + " " + std::to_string(f.counts[i].load());
  std::fprintf(stderr, "%s\n", line.c_str());
}

// Counts the operation; true (with errno set as a full disk sets it) when the plan fails this one.
bool injected(Op op) {
  auto& f = faults();
  const unsigned n = ++f.counts[std::size_t(op)];
  if (f.plan.op == op && f.plan.nth == n) {
    errno = op == Op::Rename ? EACCES : ENOSPC;
    return true;
  }
  return false;
}

std::string temporary_name(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  return path.filename().string() + ".asvgf-" + std::to_string(::getpid()) + "-" + std::to_string(++counter) +
         ".partial";
}

[[noreturn]] void fail(const std::filesystem::path& path, const char* what, int error) {
  throw FileWriteError(path.string() + ": cannot write (" + what + "): " + std::strerror(error));
}

}  // namespace

void check_file_fault_environment() {
  parse_fault(std::getenv("ASVGF_FILE_FAULT"));
}

void write_file_atomic(const std::filesystem::path& path, std::span<const std::byte> bytes) {
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  const std::filesystem::path tmp = folder / temporary_name(path);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, "create", errno);
  // Every failure below: keep the system's reason, close and remove the temporary file, throw.
  auto abandon = [&](const char* what, int error, bool close_fd) {
    if (close_fd) ::close(fd);
    ::unlink(tmp.c_str());
    fail(path, what, error);
  };
  const std::byte* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = injected(Op::Write) ? -1 : ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) abandon("write", n == 0 ? EIO : errno, true);
    p += n;
    left -= std::size_t(n);
  }
  // The bytes leave no user-space buffer (write(2) directly); the flush is the kernel's: data to disk.
  if (injected(Op::Flush) || ::fdatasync(fd) != 0) abandon("flush", errno, true);
  if (injected(Op::Sync) || ::fsync(fd) != 0) abandon("sync", errno, true);
  if (injected(Op::Close)) abandon("close", errno, true);
  if (::close(fd) != 0) abandon("close", errno, false);
  if (injected(Op::Rename) || ::rename(tmp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(tmp.c_str());
    fail(path, "rename", error);
  }
}

void write_file_atomic(const std::filesystem::path& path, std::string_view text) {
  write_file_atomic(path, std::as_bytes(std::span(text.data(), text.size())));
}

std::vector<std::filesystem::path> remove_stale_partials(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> removed;
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return removed;
  static const std::regex ours(R"(.+\.asvgf-([0-9]+)-[0-9]+\.partial)");
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (!std::regex_match(name, m, ours)) continue;
    const long pid = std::stol(m[1].str());
    const bool alive = pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno == EPERM);
    if (alive) continue;
    if (std::filesystem::remove(entry.path(), ec)) removed.push_back(entry.path());
  }
  return removed;
}

}  // namespace asvgf::render
