// Output files written whole or not at all, and what a command started cleaned up when it stops.
//
// OutputFile writes into a temporary file beside the target (same directory, so the rename is
// atomic) and renames it over the target on Commit(). The first write error (ENOSPC, EFBIG with
// SIGXFSZ ignored, EIO, ...) is kept with the system's reason; Commit() then fails naming the
// file, the temporary file is removed and the target is left as it was. Every command's output
// goes through it (trial.csv, summary.json, sweep files, compare reports, validate files,
// screenshots), so a full disk never leaves a half-written or 0-byte file behind.
//
// While open, the temporary file is listed in a process-wide table; RemoveStartedOutputs()
// (async-signal-safe) removes those files and the output directories this process created that
// are still empty: ssc calls it on SIGINT/SIGTERM and when a command fails.
#ifndef SSC_COMMON_OUTPUT_FILE_H_
#define SSC_COMMON_OUTPUT_FILE_H_

#include <memory>
#include <ostream>
#include <string>
#include <string_view>

namespace ssc {

class OutputFile {
 public:
  explicit OutputFile(std::string path);
  ~OutputFile();  // without Commit(): the temporary file is removed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Text written here is buffered and written to the temporary file.
  std::ostream& stream();
  void Write(std::string_view text);
  // Flushes, closes and renames over the target. False + *error ("PATH: cannot write: No space
  // left on device") on any error since the file was opened; nothing is left behind then.
  bool Commit(std::string* error);
  const std::string& path() const { return path_; }

 private:
  class Buffer;
  std::string path_;
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::ostream> stream_;
};

// `text` as the whole content of `path` (an OutputFile committed at once).
bool WriteWholeFile(const std::string& path, std::string_view text, std::string* error);

// Records a directory this process created (CreateOutputDir), removed again by
// RemoveStartedOutputs() when still empty. Deeper directories must be recorded after their
// parents.
void RecordCreatedOutputDir(const std::string& dir);

// Creates `dir` and its missing parents, recording each one created (RecordCreatedOutputDir).
// False + *error ("DIR: cannot create: strerror") on failure.
bool CreateRecordedDirectories(const std::string& dir, std::string* error);

// Removes the temporary files of open OutputFiles and the recorded directories that are empty.
// Async-signal-safe (unlink and rmdir on fixed tables).
void RemoveStartedOutputs();

// "PATH: what: strerror(err)".
std::string SystemError(const std::string& path, const std::string& what, int err);

}  // namespace ssc

#endif  // SSC_COMMON_OUTPUT_FILE_H_
