#include "studies/sweep_io.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/input_file.h"
#include "common/output_file.h"
#include "common/scene_files.h"
#include "common/strict_number.h"

namespace ssc {
namespace {

// Splits one CSV line into fields; quoted fields may hold commas. False on an unbalanced quote.
bool SplitFields(std::string_view line, std::vector<std::string_view>* fields) {
  fields->clear();
  size_t start = 0;
  bool quoted = false;
  for (size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || (line[i] == ',' && !quoted)) {
      fields->push_back(line.substr(start, i - start));
      start = i + 1;
    } else if (line[i] == '"') {
      quoted = !quoted;
    }
  }
  return !quoted;
}

// A metric cell: a number, or "nan" as the writer spells a value it does not have.
bool ParseMetric(std::string_view text, double* out) {
  if (text == "nan") {
    *out = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  std::string e;
  return ParseNumber(text, NumberRange(), out, &e);
}

// Column positions of the fields a resume reads, from the header.
struct Columns {
  int s_mm = -1, s_c = -1, duration_s = -1, sim_time_s = -1, iterations = -1;
};

Columns FindColumns(const std::vector<std::string_view>& header) {
  Columns c;
  for (size_t i = 0; i < header.size(); ++i) {
    const int k = static_cast<int>(i);
    if (header[i] == "s_mm") c.s_mm = k;
    if (header[i] == "s_c") c.s_c = k;
    if (header[i] == "duration_s") c.duration_s = k;
    if (header[i] == "sim_time_s") c.sim_time_s = k;
    if (header[i] == "iterations") c.iterations = k;
  }
  return c;
}

bool ParseKey(const std::vector<std::string_view>& f, const Columns& columns, SweepRowKey* key) {
  double pref = 0, beta = 0, step = 0, repeat = 0, seed = 0;
  std::string e;
  // Column order of SweepCsvHeader(): scene,pref_pa,beta,step_mm,repeat,seed,outcome,...
  if (f.size() < 7 || f[0].empty() || f[6].empty()) return false;
  if (!ParseNumber(f[1], NumberRange::Positive(1e6), &pref, &e) ||
      !ParseNumber(f[2], NumberRange::Closed(0, 100), &beta, &e) ||
      !ParseNumber(f[3], NumberRange::Positive(100), &step, &e) ||
      !ParseNumber(f[4], NumberRange::Whole(0, 1e6), &repeat, &e) ||
      !ParseNumber(f[5], kSeedRange, &seed, &e)) {
    return false;
  }
  key->pref_pa = pref;
  key->beta = beta;
  key->step_mm = step;
  key->repeat = static_cast<int>(repeat);
  key->seed = static_cast<std::uint64_t>(seed);
  key->scene = std::string(f[0]);
  key->outcome = std::string(f[6]);
  auto metric = [&](int column, double* out) {
    if (column < 0 || column >= static_cast<int>(f.size())) return;
    if (!ParseMetric(f[static_cast<size_t>(column)], out)) key->metrics_parse = false;
  };
  double iterations = 0;
  metric(columns.s_mm, &key->s_mm);
  metric(columns.s_c, &key->s_c);
  metric(columns.duration_s, &key->duration_s);
  metric(columns.sim_time_s, &key->sim_time_s);
  metric(columns.iterations, &iterations);
  if (!(iterations >= 0) || iterations != std::floor(iterations)) key->metrics_parse = false;
  key->iterations = std::isfinite(iterations) ? static_cast<long>(iterations) : -1;
  return true;
}

bool WriteWhole(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) errno = EIO;
    if (n <= 0) return false;
    text.remove_prefix(static_cast<size_t>(n));
  }
  return true;
}

}  // namespace

CsvRows ParseCsvRows(std::string_view text, std::string_view header, const CsvRowAccept& accept) {
  CsvRows c;
  std::vector<std::string_view> header_fields, fields;
  SplitFields(header, &header_fields);
  size_t pos = 0;
  int line_number = 0;
  bool first = true;
  while (pos < text.size()) {
    const size_t nl = text.find('\n', pos);
    const bool whole = nl != std::string_view::npos;
    std::string_view line = text.substr(pos, whole ? nl - pos : std::string_view::npos);
    pos = whole ? nl + 1 : text.size();
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!whole) c.ends_torn = true;
    if (first && whole && line == header) {
      c.has_header = true;
      first = false;
      continue;
    }
    first = false;
    if (whole && SplitFields(line, &fields) && fields.size() == header_fields.size() &&
        (!accept || accept(fields, line_number))) {
      c.lines.emplace_back(line);
    } else if (!line.empty() || !whole) {
      ++c.dropped;
    }
  }
  return c;
}

SweepCsvContents ParseSweepCsv(std::string_view text, std::string_view header) {
  SweepCsvContents c;
  std::vector<std::string_view> header_fields;
  SplitFields(header, &header_fields);
  const Columns columns = FindColumns(header_fields);
  CsvRows rows = ParseCsvRows(text, header, [&](const std::vector<std::string_view>& f, int line) {
    SweepRowKey key;
    if (!ParseKey(f, columns, &key)) return false;
    key.line = line;
    c.rows.push_back(key);
    return true;
  });
  c.has_header = rows.has_header;
  c.lines = std::move(rows.lines);
  c.dropped = rows.dropped;
  c.ends_torn = rows.ends_torn;
  return c;
}

namespace {

// The text of a CSV a study resumes (absent: empty; only a torn header: emptied). False +
// *error when it cannot be read or its first line is not `header`. `what`: "a sweep".
bool ReadCsvForResume(const std::string& path, const std::string& header, const std::string& what,
                      std::string* text, std::string* error) {
  text->clear();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec) &&
      !std::filesystem::is_symlink(std::filesystem::symlink_status(path, ec))) {
    return true;
  }
  if (const std::string why = CheckInputFile(path); !why.empty()) {
    *error = path + ": " + why + " (the CSV " + what + " resumes)";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = path + ": cannot read";
    return false;
  }
  std::stringstream buf;
  buf << in.rdbuf();
  *text = buf.str();
  const std::string header_line = header + "\n";
  if (header_line.compare(0, text->size(), *text, 0, header_line.size()) == 0 &&
      text->size() < header_line.size()) {
    // Empty, or a header torn while being written: start the file anew.
    const bool was_empty = text->empty();
    text->clear();
    return was_empty || WriteWholeFile(path, "", error);
  }
  if (text->compare(0, header_line.size(), header_line) != 0) {
    *error = path + ": its first line is not the header of " + what + " of this version ('" +
             header.substr(0, 40) + "...'): not a CSV that can be resumed; use another --out";
    return false;
  }
  return true;
}

}  // namespace

bool LoadSweepCsvForResume(const std::string& path, const std::string& header,
                           SweepCsvContents* contents, std::string* error) {
  *contents = SweepCsvContents();
  std::string text;
  if (!ReadCsvForResume(path, header, "a sweep", &text, error)) return false;
  if (text.empty()) return true;
  *contents = ParseSweepCsv(text, header);
  if (contents->dropped == 0) return true;
  // Rewrite without the torn or malformed lines (temp + rename: never half a file).
  return RewriteSweepCsv(path, header, contents->lines, error);
}

bool RewriteSweepCsv(const std::string& path, const std::string& header,
                     const std::vector<std::string>& lines, std::string* error) {
  OutputFile out(path);
  out.Write(header);
  out.Write("\n");
  for (const std::string& line : lines) {
    out.Write(line);
    out.Write("\n");
  }
  return out.Commit(error);
}

SweepGridKey MakeSweepGridKey(double pref_pa, double beta, double step_mm, int repeat) {
  auto q = [](double v) { return std::lround(v * 1e6); };
  return {q(pref_pa), q(beta), q(step_mm), repeat};
}

std::vector<SweepRowProblem> DropImpossibleSweepRows(const SweepRowExpectations& expect,
                                                     SweepCsvContents* contents) {
  std::vector<SweepRowProblem> problems;
  std::map<SweepGridKey, int> kept_at;  // key -> line of the row kept for it
  std::vector<SweepRowKey> rows;
  std::vector<std::string> lines;
  for (size_t i = 0; i < contents->rows.size(); ++i) {
    const SweepRowKey& r = contents->rows[i];
    std::string why;
    int kept_line = 0;
    const SweepGridKey key = MakeSweepGridKey(r.pref_pa, r.beta, r.step_mm, r.repeat);
    const bool known_outcome = std::find(expect.outcomes.begin(), expect.outcomes.end(),
                                         r.outcome) != expect.outcomes.end();
    if (r.scene != expect.scene) {
      why = "scene '" + r.scene + "' is not this sweep's '" + expect.scene + "'";
    } else if (expect.seed_of && r.seed != expect.seed_of(r)) {
      why = "seed " + std::to_string(r.seed) + " is not this grid point's seed " +
            std::to_string(expect.seed_of(r)) + " (an edited row, or another --seed)";
    } else if (!known_outcome) {
      why = "outcome '" + r.outcome + "' is not a finished trial's";
    } else if (!r.metrics_parse) {
      why = "a metric cell is not a number";
    } else if (r.outcome == expect.success &&
               !(std::isfinite(r.s_mm) && r.s_mm > 0 && std::isfinite(r.s_c) &&
                 std::isfinite(r.duration_s) && r.duration_s > 0)) {
      why = "a success with s_mm = " + FormatNumber(r.s_mm) + ", s_c = " + FormatNumber(r.s_c) +
            ", duration_s = " + FormatNumber(r.duration_s) + " (a success has a finite path)";
    } else if (!(r.sim_time_s >= 0) && !std::isnan(r.sim_time_s)) {
      why = "sim_time_s = " + FormatNumber(r.sim_time_s) + " is negative";
    } else if (const auto it = kept_at.find(key); it != kept_at.end()) {
      why = "a second row for the trial of line " + std::to_string(it->second);
      kept_line = it->second;
    }
    if (!why.empty()) {
      problems.push_back({r.line, r, why, kept_line});
      continue;
    }
    kept_at[key] = r.line;
    rows.push_back(r);
    lines.push_back(contents->lines[i]);
  }
  contents->rows = std::move(rows);
  contents->lines = std::move(lines);
  return problems;
}

SweepOutputLock::~SweepOutputLock() {
  if (fd_ < 0) return;
  // Remove the lock file while still holding the lock: a process waiting on the old file
  // finds it gone (Acquire checks the inode) and takes a new one.
  ::unlink(path_.c_str());
  ::close(fd_);
}

bool SweepOutputLock::Acquire(const std::string& csv_path, std::string* error) {
  path_ = csv_path + ".lock";
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
      *error = SystemError(path_, "cannot create the sweep lock", errno);
      return false;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      char text[32] = {};
      const ssize_t n = ::pread(fd, text, sizeof(text) - 1, 0);
      ::close(fd);
      if (err != EWOULDBLOCK) {
        *error = SystemError(path_, "cannot lock", err);
        return false;
      }
      std::string pid = n > 0 ? std::string(text, static_cast<size_t>(n)) : "";
      while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
      *error = csv_path + " is being written by another sweep (pid " +
               (pid.empty() ? std::string("unknown") : pid) + ", lock " + path_ +
               "): wait for it to end, or use another --out";
      return false;
    }
    // The holder may have removed the file between our open and flock: lock the current one.
    struct stat held, now;
    if (::fstat(fd, &held) != 0 || ::stat(path_.c_str(), &now) != 0 || held.st_ino != now.st_ino ||
        held.st_dev != now.st_dev) {
      ::close(fd);
      continue;
    }
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) < 0) {
      *error = SystemError(path_, "cannot write the sweep lock", errno);
      ::unlink(path_.c_str());
      ::close(fd);
      return false;
    }
    fd_ = fd;
    return true;
  }
  *error = path_ + ": the sweep lock keeps changing hands; try again";
  return false;
}

SweepRowWriter::~SweepRowWriter() {
  if (fd_ >= 0) ::close(fd_);
}

bool SweepRowWriter::Open(const std::string& path, std::string* error) {
  path_ = path;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    *error = path + ": cannot open for appending: " + std::strerror(errno);
    return false;
  }
  return true;
}

bool SweepRowWriter::Append(std::string_view row, std::string* error) {
  std::string line(row);
  for (char& ch : line) {
    if (ch == '\n' || ch == '\r') ch = ' ';
  }
  line += '\n';
  // A row that cannot be written whole (a full disk, a file-size limit) is cut off again, so
  // the file ends on a whole row.
  const off_t before = fd_ >= 0 ? ::lseek(fd_, 0, SEEK_END) : -1;
  if (fd_ < 0 || !WriteWhole(fd_, line)) {
    const int err = fd_ < 0 ? EBADF : errno;
    if (before >= 0 && ::ftruncate(fd_, before) != 0) {
      // Left torn: the next resume drops the partial row.
    }
    *error = SystemError(path_, "cannot append a row", err);
    return false;
  }
  return true;
}

std::string SweepManifestPath(const std::string& csv_path) {
  return std::filesystem::path(csv_path).replace_extension(".json").string();
}

namespace {

// A value whose text is a JSON number or boolean, written back exactly as that text, is stored
// as that type (sweep.json holds 30, not "30"); any other text stays a string. Either way the
// text round-trips.
nlohmann::json ManifestValue(const std::string& text) {
  const nlohmann::json typed = nlohmann::json::parse(text, nullptr, false);
  if (!typed.is_discarded() && (typed.is_number() || typed.is_boolean()) && typed.dump() == text) {
    return typed;
  }
  return text;
}

}  // namespace

std::string SweepManifestJson(const SweepManifest& manifest) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [k, v] : manifest) j[k] = ManifestValue(v);
  return j.dump(2) + "\n";
}

bool ParseSweepManifest(std::string_view json, SweepManifest* manifest, std::string* error) {
  manifest->clear();
  const nlohmann::json j = nlohmann::json::parse(json.begin(), json.end(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    *error = "not a JSON object";
    return false;
  }
  for (const auto& [k, v] : j.items()) {
    if (v.is_string()) {
      (*manifest)[k] = v.get<std::string>();
    } else if (v.is_number() || v.is_boolean()) {
      (*manifest)[k] = v.dump();  // the text it was written from (SweepManifestJson)
    } else {
      *error = "'" + k + "' is not a string, number or boolean";
      return false;
    }
  }
  return true;
}

std::string CompareSweepManifests(const SweepManifest& recorded, const SweepManifest& now) {
  std::string diff;
  auto add = [&diff](const std::string& s) { diff += (diff.empty() ? "" : "; ") + s; };
  auto information = [](const std::string& k) {
    for (const char* key : kSweepManifestInformationKeys)
      if (k == key) return true;
    return false;
  };
  for (const auto& [k, v] : now) {
    if (information(k)) continue;
    auto it = recorded.find(k);
    if (it == recorded.end()) {
      add(k + ": not recorded, " + v + " now");
    } else if (it->second != v) {
      add(k + ": " + it->second + " in the file, " + v + " now");
    }
  }
  for (const auto& [k, v] : recorded) {
    if (!information(k) && !now.count(k)) add(k + ": " + v + " in the file, not set now");
  }
  return diff;
}

bool CheckOrWriteSweepManifest(const std::string& csv_path, bool csv_has_rows,
                               const SweepManifest& now, std::string* error) {
  const std::string path = SweepManifestPath(csv_path);
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    if (const std::string why = CheckInputFile(path); !why.empty()) {
      *error = path + ": " + why;
      return false;
    }
    std::ifstream in(path);
    std::stringstream buf;
    buf << in.rdbuf();
    SweepManifest recorded;
    std::string e;
    if (!ParseSweepManifest(buf.str(), &recorded, &e)) {
      *error = path + ": " + e + "; cannot tell which options made the rows in " + csv_path +
               " (use another --out)";
      return false;
    }
    if (const std::string diff = CompareSweepManifests(recorded, now); !diff.empty()) {
      *error = csv_path + " holds rows made with other options (" + diff +
               "); resuming would mix them: use another --out, or the same options";
      return false;
    }
    return true;
  }
  if (csv_has_rows) {
    *error = csv_path + " has rows but no " + path +
             ": cannot tell which options made them (use another --out)";
    return false;
  }
  return WriteWholeFile(path, SweepManifestJson(now), error);
}

namespace {

constexpr const char* kRowDigestColumn = "row_digest";

std::string RowDigest(std::string_view row) {
  char hex[32];
  std::snprintf(hex, sizeof(hex), "%016llx",
                static_cast<unsigned long long>(Fnv1a64(row.data(), row.size())));
  return hex;
}

std::string WithDigest(std::string_view row) { return std::string(row) + "," + RowDigest(row); }

}  // namespace

bool ResumableTable::Open(const std::string& path, const std::string& header,
                          const SweepManifest& manifest, const RowCheck& check,
                          const std::string& what, std::string* error) {
  path_ = path;
  header_ = header + "," + kRowDigestColumn;
  kept_.clear();
  std::string text;
  if (!lock_.Acquire(path, error) || !ReadCsvForResume(path, header_, what, &text, error)) {
    return false;
  }
  std::vector<std::string> keys, whys;  // per whole row: its key ("" when refused) and why
  CsvRows rows = ParseCsvRows(text, header_, [&](const std::vector<std::string_view>& f, int) {
    const std::vector<std::string_view> fields(f.begin(), f.end() - 1);
    std::string why;
    keys.push_back(check(fields, &why));
    whys.push_back(why);
    return true;
  });
  if (!CheckOrWriteSweepManifest(path, !rows.lines.empty(), manifest, error)) return false;
  std::vector<std::string> keep;
  int problems = 0;
  for (size_t i = 0; i < rows.lines.size(); ++i) {
    // The digest seals the row as the study wrote it: a row changed since (an outcome edited
    // to contradict its own detail) cannot be trusted as a finished trial.
    const std::string& sealed = rows.lines[i];
    const std::size_t comma = sealed.rfind(',');
    const std::string line = sealed.substr(0, comma);
    std::string key = keys[i], why = whys[i];
    if (!key.empty() && sealed.compare(comma + 1, std::string::npos, RowDigest(line)) != 0) {
      key.clear();
      why = std::string(kRowDigestColumn) + " does not match the row: changed since it was written";
    }
    if (!key.empty() && kept_.count(key)) {
      why = "a second row for " + key;
      key.clear();
    }
    if (key.empty()) {
      if (++problems <= 10) {
        std::fprintf(stderr, "%s: %s: row '%s': %s; dropped, the trial runs again\n", what.c_str(),
                     path.c_str(), line.substr(0, 60).c_str(), why.c_str());
      }
      continue;
    }
    kept_[key] = line;
    keep.push_back(line);
  }
  if (problems > 10) {
    std::fprintf(stderr, "%s: %d more rows of %s like these dropped\n", what.c_str(), problems - 10,
                 path.c_str());
  }
  if (rows.dropped > 0) {
    std::fprintf(stderr,
                 "%s: dropped %d torn or malformed line(s) from %s; those trials run again\n",
                 what.c_str(), rows.dropped, path.c_str());
  }
  if ((rows.dropped > 0 || problems > 0 || !rows.has_header) && !Rewrite(keep, error)) return false;
  return writer_.Open(path, error);
}

std::string ResumableTable::Kept(const std::string& key) const {
  const auto it = kept_.find(key);
  return it == kept_.end() ? "" : it->second;
}

bool ResumableTable::Append(std::string_view row, std::string* error) {
  return writer_.Append(WithDigest(row), error);
}

bool ResumableTable::Rewrite(const std::vector<std::string>& rows, std::string* error) {
  std::vector<std::string> sealed;
  sealed.reserve(rows.size());
  for (const std::string& row : rows) sealed.push_back(WithDigest(row));
  return RewriteSweepCsv(path_, header_, sealed, error);
}

std::uint64_t Fnv1a64(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t h = 1469598103934665603ULL;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ULL;
  return h;
}

std::map<std::string, std::string> SceneFileHashes(const std::string& scene_path) {
  namespace fs = std::filesystem;
  std::map<std::string, std::string> hashes;
  auto hash_file = [&hashes](const fs::path& path) {
    if (hashes.count(path.string())) return;
    std::string& h = hashes[path.string()];
    if (const std::string why = CheckInputFile(path.string()); !why.empty()) {
      h = why;  // never read: a FIFO would block
      return;
    }
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    const std::string bytes = text.str();
    char hex[32];
    std::snprintf(hex, sizeof(hex), "%016llx",
                  static_cast<unsigned long long>(Fnv1a64(bytes.data(), bytes.size())));
    h = hex;
  };
  const fs::path scene = fs::absolute(scene_path).lexically_normal();
  hash_file(scene);
  const std::string stopped = WalkSceneFiles(scene, [&](const SceneFileRef& ref) {
    if (ref.found.empty()) hash_file((ref.from.parent_path() / ref.name).lexically_normal());
    for (const fs::path& place : ref.found) hash_file(place);
    return std::string();
  });
  if (!stopped.empty()) hashes[scene.string() + " walk"] = stopped;
  return hashes;
}

}  // namespace ssc
