// Sweep files, resumable and safe against interruption: the CSV rows (each written whole or not
// at all) and the manifest beside the CSV (the options that define the rows). Self-contained
// (std + POSIX + nlohmann-json, no MuJoCo), so the sweep, the job runner's writer rank and the
// fuzz target (studies/fuzz/sweep_resume_fuzz.cc) share it.
//
// Resume rules: a line counts as a finished trial only when it ends in '\n', has exactly the
// header's number of fields (quoted fields respected) and its key fields (pref_pa, beta,
// step_mm, repeat, seed) parse strictly. Anything else (a torn tail from a killed run, a torn
// row that a later append glued onto) is dropped, the file is rewritten without it, and those
// trials run again. Then no row is trusted: one whose seed is not its grid point's, whose scene
// or outcome is not this sweep's, whose metrics a finished trial cannot have (a success with
// s_mm = nan), or that repeats a key already kept is dropped too, named on stderr, and rerun.
#ifndef SSC_STUDIES_SWEEP_IO_H_
#define SSC_STUDIES_SWEEP_IO_H_

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace ssc {

struct SweepRowKey {
  double pref_pa = 0, beta = 0, step_mm = 0;
  int repeat = 0;
  std::uint64_t seed = 0;
  std::string scene, outcome;
  // The metrics as numbers ("nan" -> NaN); false when a metric cell is not a number at all.
  double s_mm = 0, s_c = 0, duration_s = 0, sim_time_s = 0;
  long iterations = 0;
  bool metrics_parse = true;
  int line = 0;  // 1-based line number in the file
};

struct SweepCsvContents {
  bool has_header = false;
  std::vector<SweepRowKey> rows;   // the whole rows, in file order
  std::vector<std::string> lines;  // their text (without '\n'), same order
  int dropped = 0;                 // torn or malformed lines
  bool ends_torn = false;          // the last line has no '\n'
};

// Parses a sweep CSV's text; `header` is the expected first line (without '\n').
SweepCsvContents ParseSweepCsv(std::string_view text, std::string_view header);

// The whole rows of any study's CSV, by the sweep's rules (a line ending in '\n' with the
// header's number of fields, quoted fields respected) and `accept` (the row's own fields, its
// 1-based line number; null: every such row): the rest counted in `dropped`.
struct CsvRows {
  bool has_header = false;
  std::vector<std::string> lines;  // without '\n'
  int dropped = 0;
  bool ends_torn = false;
};
using CsvRowAccept = std::function<bool(const std::vector<std::string_view>& fields, int line)>;
CsvRows ParseCsvRows(std::string_view text, std::string_view header, const CsvRowAccept& accept);

// Reads `path` (absent = empty) for resuming. When any line was dropped, rewrites the file
// (temp file + rename) with the header and the whole rows only, so later appends start on a
// fresh line. False + *error when the file cannot be read or rewritten, or its header differs.
bool LoadSweepCsvForResume(const std::string& path, const std::string& header,
                           SweepCsvContents* contents, std::string* error);

// The grid point of a row, in 1e-6 units (P_ref Pa, beta, step mm) and its repeat: two rows with
// one key are the same trial.
using SweepGridKey = std::tuple<long, long, long, int>;
SweepGridKey MakeSweepGridKey(double pref_pa, double beta, double step_mm, int repeat);

// What a resuming sweep expects of every row it keeps.
struct SweepRowExpectations {
  std::string scene;
  std::function<std::uint64_t(const SweepRowKey&)> seed_of;  // the seed its grid point gets
  std::vector<std::string> outcomes;                         // names of finished outcomes
  std::string success;                                       // the success outcome's name
};

// A row that cannot be a finished trial of this sweep, and why ("seed 12 is not this grid
// point's seed 4711", "a duplicate of line 3", "success with s_mm = nan").
struct SweepRowProblem {
  int line = 0;
  SweepRowKey row;
  std::string why;
  int kept_line = 0;  // a duplicate: the line of the row kept for its trial (0: none kept)
};

// Checks every row of `contents` against `expect` (scene, seed derived from the grid point, a
// known outcome, metrics a finished trial can have, one row per key: the first good one wins)
// and removes the bad ones from `contents`, returning them.
std::vector<SweepRowProblem> DropImpossibleSweepRows(const SweepRowExpectations& expect,
                                                     SweepCsvContents* contents);

// Rewrites `path` with the header and `lines` (a temporary file renamed over it).
bool RewriteSweepCsv(const std::string& path, const std::string& header,
                     const std::vector<std::string>& lines, std::string* error);

// One sweep at a time per output: an exclusive flock(2) on CSV.lock (holding the owner's pid),
// taken before the CSV is read and released (the lock file removed) by the destructor. A second
// process is refused naming the pid that holds it.
class SweepOutputLock {
 public:
  SweepOutputLock() = default;
  ~SweepOutputLock();
  SweepOutputLock(const SweepOutputLock&) = delete;
  SweepOutputLock& operator=(const SweepOutputLock&) = delete;
  bool Acquire(const std::string& csv_path, std::string* error);

 private:
  int fd_ = -1;
  std::string path_;
};

// Appends rows to a sweep CSV, each with one write(2) on an O_APPEND descriptor and newlines
// inside a row replaced by spaces (a row never spans lines).
class SweepRowWriter {
 public:
  SweepRowWriter() = default;
  ~SweepRowWriter();
  SweepRowWriter(const SweepRowWriter&) = delete;
  SweepRowWriter& operator=(const SweepRowWriter&) = delete;
  bool Open(const std::string& path, std::string* error);
  bool Append(std::string_view row, std::string* error);

 private:
  int fd_ = -1;
  std::string path_;
};

// The options that define a sweep's rows (scene, seed, timeout, thresholds, model hash, ...),
// as name -> value text. Stored as JSON beside the CSV (sweep.csv -> sweep.json): numbers and
// booleans as JSON numbers and booleans, the rest as strings; reading gives the same texts back.
using SweepManifest = std::map<std::string, std::string>;

std::string SweepManifestPath(const std::string& csv_path);
std::string SweepManifestJson(const SweepManifest& manifest);
// False + *error on malformed JSON or a value that is not a string, number or boolean.
bool ParseSweepManifest(std::string_view json, SweepManifest* manifest, std::string* error);
// Keys a manifest records for the reader that do not define the rows: the project's default
// scene when the sweep ran (the rows are defined by "scene"). Comparisons skip them.
inline constexpr const char* kSweepManifestInformationKeys[] = {"default_scene"};

// "" when equal; else one line naming each difference ("seed: 1 in the file, 2 now"); the
// information keys are not compared.
std::string CompareSweepManifests(const SweepManifest& recorded, const SweepManifest& now);

// Checks `now` against the manifest beside `csv_path`, or writes it when there is none and the
// CSV holds no rows yet. False + *error (naming the differences) when resuming would mix rows
// made with other options.
bool CheckOrWriteSweepManifest(const std::string& csv_path, bool csv_has_rows,
                               const SweepManifest& now, std::string* error);

// A study's results table that resumes as a sweep's CSV does: one run per table at a time (the
// sweep's lock), the options that define its rows beside it (TABLE.json, compared on resume:
// other options are refused naming the differences), rows appended whole as trials finish, and
// on resume only whole rows kept that `check` accepts, once per key; a row refused or repeated
// is dropped, named on stderr, and its trial runs again. Each row ends in a row_digest column
// (FNV-1a of the rest of the row, added on Append and Rewrite, checked and stripped on Open): a
// row changed since it was written is refused like any other. Rows in and out of this class are
// the study's own, without the digest.
class ResumableTable {
 public:
  // The row's key from its fields, or "" with *why saying why the row cannot be this run's.
  using RowCheck =
      std::function<std::string(const std::vector<std::string_view>& fields, std::string* why)>;
  // `what` names the study in messages ("ssc objects").
  bool Open(const std::string& path, const std::string& header, const SweepManifest& manifest,
            const RowCheck& check, const std::string& what, std::string* error);
  // The row kept for `key` from an earlier run ("" when none).
  std::string Kept(const std::string& key) const;
  std::size_t kept() const { return kept_.size(); }
  bool Append(std::string_view row, std::string* error);
  // The table rewritten as the header and `rows` (the study's order, once every trial finished).
  bool Rewrite(const std::vector<std::string>& rows, std::string* error);

 private:
  SweepOutputLock lock_;
  SweepRowWriter writer_;
  std::string path_, header_;
  std::map<std::string, std::string> kept_;
};

// 64-bit FNV-1a, for the model hash.
std::uint64_t Fnv1a64(const void* data, std::size_t size);

// What a scene's rows depend on, read from its files without compiling it: the scene and every
// file it pulls in (common/scene_files.h: includes and attached models recursively, meshes,
// textures, ...), as absolute path -> the FNV-1a hash of its bytes ("%016llx"). A file that cannot
// be read maps to why (common/input_file.h: "no such file", a FIFO is never read), and a walk that
// stops (nested too deep) records its message under the scene's path + " walk".
std::map<std::string, std::string> SceneFileHashes(const std::string& scene_path);

}  // namespace ssc

#endif  // SSC_STUDIES_SWEEP_IO_H_
