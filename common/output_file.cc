#include "common/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <streambuf>
#include <vector>

namespace ssc {
namespace {

// Fixed tables readable from a signal handler: a slot is free (0), being filled (1) or holds a
// path (2).
constexpr int kSlots = 64;
constexpr int kPathMax = 4096;
struct Slot {
  std::atomic<int> state{0};
  char path[kPathMax];
};
Slot g_temp_files[kSlots];
Slot g_created_dirs[kSlots];

int TakeSlot(Slot* table, const std::string& path) {
  if (path.size() >= kPathMax) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (table[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(table[i].path, path.c_str(), path.size() + 1);
      table[i].state.store(2);
      return i;
    }
  }
  return -1;  // table full: the file is still written whole, only not removed on a signal
}

std::atomic<unsigned> g_temp_counter{0};

}  // namespace

std::string SystemError(const std::string& path, const std::string& what, int err) {
  return path + ": " + what + ": " + std::strerror(err);
}

// Writes through a 64 KiB buffer to the descriptor; keeps the first error.
class OutputFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(const std::string& target) {
    const std::string name = target + ".tmp" + std::to_string(::getpid()) + "_" +
                             std::to_string(g_temp_counter.fetch_add(1));
    temp_ = name;
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0) {
      error_ = errno;
      what_ = "cannot create";
      return;
    }
    slot_ = TakeSlot(g_temp_files, temp_);
    data_.resize(1 << 16);
    setp(data_.data(), data_.data() + data_.size());
  }
  ~Buffer() override { Discard(); }

  bool Finish(const std::string& target, std::string* error) {
    if (error_ == 0) Drain();
    if (fd_ >= 0 && ::close(fd_) != 0 && error_ == 0) {
      error_ = errno;
      what_ = "cannot write";
    }
    fd_ = -1;
    if (error_ == 0 && std::rename(temp_.c_str(), target.c_str()) != 0) {
      error_ = errno;
      what_ = "cannot replace";
    }
    if (error_ != 0) {
      *error = SystemError(target, what_, error_);
      Discard();
      return false;
    }
    Release();
    return true;
  }

 protected:
  int overflow(int ch) override {
    if (!Drain()) return traits_type::eof();
    if (ch != traits_type::eof()) {
      *pptr() = static_cast<char>(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return Drain() ? 0 : -1; }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n > epptr() - pptr()) {
      if (!Drain()) return 0;
      if (n > epptr() - pptr()) return WriteAll(s, static_cast<size_t>(n)) ? n : 0;
    }
    std::memcpy(pptr(), s, static_cast<size_t>(n));
    pbump(static_cast<int>(n));
    return n;
  }

 private:
  bool WriteAll(const char* p, size_t n) {
    if (error_ != 0) return false;
    while (n > 0) {
      const ssize_t w = ::write(fd_, p, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        error_ = w < 0 ? errno : EIO;
        what_ = "cannot write";
        return false;
      }
      p += w;
      n -= static_cast<size_t>(w);
    }
    return true;
  }
  bool Drain() {
    if (error_ != 0 || fd_ < 0) return false;
    const bool ok = WriteAll(pbase(), static_cast<size_t>(pptr() - pbase()));
    setp(data_.data(), data_.data() + data_.size());
    return ok;
  }
  void Release() {
    if (slot_ >= 0) g_temp_files[slot_].state.store(0);
    slot_ = -1;
    temp_.clear();
  }
  void Discard() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!temp_.empty()) ::unlink(temp_.c_str());
    Release();
  }

  int fd_ = -1;
  int slot_ = -1;
  int error_ = 0;
  std::string what_;
  std::string temp_;
  std::vector<char> data_;
};

OutputFile::OutputFile(std::string path)
    : path_(std::move(path)),
      buffer_(std::make_unique<Buffer>(path_)),
      stream_(std::make_unique<std::ostream>(buffer_.get())) {}

OutputFile::~OutputFile() = default;

std::ostream& OutputFile::stream() { return *stream_; }

void OutputFile::Write(std::string_view text) {
  stream_->write(text.data(), static_cast<std::streamsize>(text.size()));
}

bool OutputFile::Commit(std::string* error) {
  stream_->flush();
  return buffer_->Finish(path_, error);
}

bool WriteWholeFile(const std::string& path, std::string_view text, std::string* error) {
  OutputFile file(path);
  file.Write(text);
  return file.Commit(error);
}

void RecordCreatedOutputDir(const std::string& dir) { TakeSlot(g_created_dirs, dir); }

bool CreateRecordedDirectories(const std::string& dir, std::string* error) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // The folders this creates, parent first.
  std::vector<fs::path> missing;
  fs::path start = fs::absolute(dir, ec).lexically_normal();
  if (start.filename().empty()) start = start.parent_path();  // "out/" -> "out"
  for (fs::path q = start; !q.empty() && !fs::exists(q, ec); q = q.parent_path()) {
    missing.push_back(q);
    if (q == q.parent_path()) break;
  }
  fs::create_directories(dir, ec);
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (fs::is_directory(*it)) RecordCreatedOutputDir(it->string());
  }
  if (ec || !fs::is_directory(dir)) {
    *error = dir + ": cannot create the directory: " +
             (ec ? ec.message() : std::string("not a directory"));
    return false;
  }
  return true;
}

void RemoveStartedOutputs() {
  for (Slot& s : g_temp_files) {
    if (s.state.load() == 2) ::unlink(s.path);
  }
  // Deepest first: the slots were taken parent before child.
  for (int i = kSlots - 1; i >= 0; --i) {
    if (g_created_dirs[i].state.load() == 2) ::rmdir(g_created_dirs[i].path);
  }
}

}  // namespace ssc
