#include "studies/sweep_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/input_file.h"
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

bool ParseKey(const std::vector<std::string_view>& f, SweepRowKey* key) {
  double pref = 0, beta = 0, step = 0, repeat = 0, seed = 0;
  std::string e;
  // Column order of SweepCsvHeader(): scene,pref_pa,beta,step_mm,repeat,seed,outcome,...
  if (f.size() < 7 || f[0].empty() || f[6].empty()) return false;
  if (!ParseNumber(f[1], NumberRange::Positive(1e6), &pref, &e) ||
      !ParseNumber(f[2], NumberRange::Closed(0, 100), &beta, &e) ||
      !ParseNumber(f[3], NumberRange::Positive(100), &step, &e) ||
      !ParseNumber(f[4], NumberRange::Whole(0, 1e6), &repeat, &e) ||
      !ParseNumber(f[5], NumberRange::Whole(0, 9007199254740991.0), &seed, &e)) {
    return false;
  }
  *key = {pref, beta, step, static_cast<int>(repeat), static_cast<std::uint64_t>(seed)};
  return true;
}

bool WriteWhole(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    text.remove_prefix(static_cast<size_t>(n));
  }
  return true;
}

}  // namespace

SweepCsvContents ParseSweepCsv(std::string_view text, std::string_view header) {
  SweepCsvContents c;
  std::vector<std::string_view> header_fields, fields;
  SplitFields(header, &header_fields);
  size_t pos = 0;
  bool first = true;
  while (pos < text.size()) {
    const size_t nl = text.find('\n', pos);
    const bool whole = nl != std::string_view::npos;
    std::string_view line = text.substr(pos, whole ? nl - pos : std::string_view::npos);
    pos = whole ? nl + 1 : text.size();
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!whole) c.ends_torn = true;
    if (first && whole && line == header) {
      c.has_header = true;
      first = false;
      continue;
    }
    first = false;
    SweepRowKey key;
    if (whole && SplitFields(line, &fields) && fields.size() == header_fields.size() &&
        ParseKey(fields, &key)) {
      c.rows.push_back(key);
      c.lines.emplace_back(line);
    } else if (!line.empty() || !whole) {
      ++c.dropped;
    }
  }
  return c;
}

bool LoadSweepCsvForResume(const std::string& path, const std::string& header,
                           SweepCsvContents* contents, std::string* error) {
  *contents = SweepCsvContents();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec) &&
      !std::filesystem::is_symlink(std::filesystem::symlink_status(path, ec))) {
    return true;
  }
  if (const std::string why = CheckInputFile(path); !why.empty()) {
    *error = path + ": " + why + " (the CSV a sweep resumes)";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = path + ": cannot read";
    return false;
  }
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  const std::string header_line = header + "\n";
  if (header_line.compare(0, text.size(), text, 0, header_line.size()) == 0 &&
      text.size() < header_line.size()) {
    // Empty, or a header torn while being written: start the file anew.
    if (!text.empty()) std::ofstream(path, std::ios::binary | std::ios::trunc);
    return true;
  }
  if (text.compare(0, header_line.size(), header_line) != 0) {
    *error = path + ": its first line is not this version's sweep header ('" +
             header.substr(0, 40) + "...'): not a sweep CSV that can be resumed; use another --out";
    return false;
  }
  *contents = ParseSweepCsv(text, header);
  if (contents->dropped == 0) return true;
  // Rewrite without the torn or malformed lines (temp + rename: never half a file).
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << header << '\n';
    for (const std::string& line : contents->lines) out << line << '\n';
    out.flush();
    if (!out) {
      *error = tmp + ": cannot write";
      return false;
    }
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    *error = path + ": cannot replace: " + ec.message();
    return false;
  }
  return true;
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
  if (fd_ < 0 || !WriteWhole(fd_, line)) {
    *error = path_ + ": cannot append a row: " + std::strerror(errno);
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
  for (const auto& [k, v] : now) {
    auto it = recorded.find(k);
    if (it == recorded.end()) {
      add(k + ": not recorded, " + v + " now");
    } else if (it->second != v) {
      add(k + ": " + it->second + " in the file, " + v + " now");
    }
  }
  for (const auto& [k, v] : recorded) {
    if (!now.count(k)) add(k + ": " + v + " in the file, not set now");
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
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << SweepManifestJson(now);
    out.flush();
    if (!out) {
      *error = tmp + ": cannot write";
      return false;
    }
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    *error = path + ": cannot write: " + ec.message();
    return false;
  }
  return true;
}

std::uint64_t Fnv1a64(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t h = 1469598103934665603ULL;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ULL;
  return h;
}

}  // namespace ssc
