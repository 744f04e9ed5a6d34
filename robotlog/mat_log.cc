#include "robotlog/mat_log.h"

#include <matio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "robotlog/robot_log.h"
#include "robotlog/text_cells.h"
#include "robotlog/topic_csv.h"

namespace ssc {
namespace {

struct MatCloser {
  void operator()(mat_t* m) const { Mat_Close(m); }
};
struct VarFreer {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using MatPtr = std::unique_ptr<mat_t, MatCloser>;
using VarPtr = std::unique_ptr<matvar_t, VarFreer>;

constexpr char kColumnSuffix[] = "_columnName";
constexpr char kDataSuffix[] = "_data";
constexpr size_t kHistoryColumns = 11;  // t, x, y, r_p, corr_p, r_p_final, F, P1..P4

// A level-5 MAT file is a 128-byte header and a chain of top-level elements, each a tag (type,
// byte count) and its bytes. matio stops quietly at an element cut short, so a truncated file
// (a copy that did not finish, a disk that filled up) would lose its last variables without a
// word: walk the chain and require it to end exactly at the end of the file. Other versions
// (v4 without a header, v7.3 = HDF5) are left to matio.
bool CheckMat5Complete(const std::string& path, LoadError* error) {
  std::ifstream f(path, std::ios::binary);
  unsigned char header[128];
  if (!f.read(reinterpret_cast<char*>(header), sizeof(header))) return true;  // matio decides
  const bool little = header[126] == 'I' && header[127] == 'M';
  const bool big = header[126] == 'M' && header[127] == 'I';
  if (!little && !big) return true;
  auto u16 = [&](const unsigned char* b) {
    return little ? static_cast<unsigned>(b[0] | b[1] << 8)
                  : static_cast<unsigned>(b[1] | b[0] << 8);
  };
  auto u32 = [&](const unsigned char* b) {
    return little ? (std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 | std::uint32_t{b[2]} << 16 |
                     std::uint32_t{b[3]} << 24)
                  : (std::uint32_t{b[3]} | std::uint32_t{b[2]} << 8 | std::uint32_t{b[1]} << 16 |
                     std::uint32_t{b[0]} << 24);
  };
  if (u16(header + 124) != 0x0100) return true;  // not level 5
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return true;
  std::uintmax_t offset = sizeof(header);
  for (int element = 1; offset < size; ++element) {
    unsigned char tag[8];
    f.seekg(static_cast<std::streamoff>(offset));
    const bool whole_tag = size - offset >= 8 && f.read(reinterpret_cast<char*>(tag), 8);
    const std::uint32_t type = whole_tag ? u32(tag) : 0;
    std::uintmax_t end = offset + 8;  // (a small element keeps its data in the tag)
    if (whole_tag && (type >> 16) == 0) end += u32(tag + 4);
    if (!whole_tag || end > size) {
      text::SetError(error, path, 0, 0,
                     "the file is cut short: top-level element " + std::to_string(element) +
                         " (at byte " + std::to_string(offset) + ") ends at byte " +
                         std::to_string(end) + ", the file has " + std::to_string(size) +
                         " (an unfinished copy or save?); variables after it would be lost");
      return false;
    }
    // Elements start on 8-byte boundaries, except after miCOMPRESSED (type 15).
    offset = type == 15 ? end : std::min<std::uintmax_t>((end + 7) / 8 * 8, size);
  }
  return true;
}

template <typename T>
void Convert(const void* data, size_t n, std::vector<double>* out) {
  const T* p = static_cast<const T*>(data);
  out->resize(n);
  for (size_t i = 0; i < n; ++i) (*out)[i] = static_cast<double>(p[i]);
}

size_t Elements(const matvar_t* v) {
  size_t n = 1;
  for (int k = 0; k < v->rank; ++k) n *= v->dims[k];
  return n;
}

// A real numeric variable's elements as doubles (column-major); false otherwise.
bool ToDoubles(const matvar_t* v, std::vector<double>* out) {
  if (v->class_type < MAT_C_DOUBLE || v->class_type > MAT_C_UINT64 || v->isComplex ||
      v->class_type == MAT_C_SPARSE || v->data == nullptr) {
    return false;
  }
  const size_t n = Elements(v);
  switch (v->data_type) {
    case MAT_T_DOUBLE:
      Convert<double>(v->data, n, out);
      return true;
    case MAT_T_SINGLE:
      Convert<float>(v->data, n, out);
      return true;
    case MAT_T_INT8:
      Convert<int8_t>(v->data, n, out);
      return true;
    case MAT_T_UINT8:
      Convert<uint8_t>(v->data, n, out);
      return true;
    case MAT_T_INT16:
      Convert<int16_t>(v->data, n, out);
      return true;
    case MAT_T_UINT16:
      Convert<uint16_t>(v->data, n, out);
      return true;
    case MAT_T_INT32:
      Convert<int32_t>(v->data, n, out);
      return true;
    case MAT_T_UINT32:
      Convert<uint32_t>(v->data, n, out);
      return true;
    case MAT_T_INT64:
      Convert<int64_t>(v->data, n, out);
      return true;
    case MAT_T_UINT64:
      Convert<uint64_t>(v->data, n, out);
      return true;
    default:
      return false;
  }
}

// The rows of a char matrix, trailing blanks dropped; false if it is not a char matrix.
bool CharRows(const matvar_t* v, std::vector<std::string>* rows) {
  if (v->class_type != MAT_C_CHAR || v->rank != 2 || v->data == nullptr) return false;
  const size_t n = v->dims[0], len = v->dims[1];
  size_t width = 1;
  if (v->data_type == MAT_T_UINT16 || v->data_type == MAT_T_UTF16 || v->data_type == MAT_T_INT16) {
    width = 2;
  } else if (v->data_type == MAT_T_UINT32 || v->data_type == MAT_T_UTF32) {
    width = 4;
  }
  if (v->nbytes < n * len * width) return false;
  rows->assign(n, std::string());
  for (size_t r = 0; r < n; ++r) {
    for (size_t c = 0; c < len; ++c) {
      const size_t k = c * n + r;  // column-major
      uint32_t code = 0;
      if (width == 1) code = static_cast<const uint8_t*>(v->data)[k];
      if (width == 2) code = static_cast<const uint16_t*>(v->data)[k];
      if (width == 4) code = static_cast<const uint32_t*>(v->data)[k];
      (*rows)[r] += code < 0x80 ? static_cast<char>(code) : '?';
    }
    const size_t end = (*rows)[r].find_last_not_of(' ');
    (*rows)[r].resize(end == std::string::npos ? 0 : end + 1);
  }
  return true;
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::vector<std::string> VariableNames(mat_t* mat) {
  std::vector<std::string> names;
  Mat_Rewind(mat);
  for (VarPtr v(Mat_VarReadNextInfo(mat)); v; v.reset(Mat_VarReadNextInfo(mat))) {
    if (v->name != nullptr) names.emplace_back(v->name);
  }
  return names;
}

// One topic's pair of variables -> a table of rows (like a parsed CSV).
bool ReadTopicPair(mat_t* mat, const std::string& path, const std::string& prefix,
                   TopicTable* table, LoadError* e) {
  const std::string names_var = prefix + kColumnSuffix, data_var = prefix + kDataSuffix;
  VarPtr names(Mat_VarRead(mat, names_var.c_str()));
  std::vector<std::string> columns;
  if (!names || !CharRows(names.get(), &columns) || columns.empty()) {
    text::SetError(
        e, path, 0, 0,
        "variable '" + names_var + "': expected a char matrix of " + "column names (one per row)");
    return false;
  }
  std::vector<std::string_view> views(columns.begin(), columns.end());
  LoadError header_error;
  if (!ParseTopicHeader(views, path, 0, &table->header, &header_error)) {
    text::SetError(e, path, header_error.column, 0,
                   "variable '" + names_var + "' row " + std::to_string(header_error.column) +
                       ": " + header_error.message);
    e->column = 0;
    return false;
  }
  if (table->header.topic == nullptr) return true;  // a topic the twin does not use
  const std::string what = "variable '" + data_var + "': ";
  VarPtr data(Mat_VarRead(mat, data_var.c_str()));
  if (!data) {
    text::SetError(e, path, 0, 0, what + "missing (its column names are in '" + names_var + "')");
    return false;
  }
  const size_t cols = columns.size();
  std::vector<double> v;
  if (data->rank != 2 || !ToDoubles(data.get(), &v)) {
    text::SetError(e, path, 0, 0, what + "must be a real numeric matrix (one row per sample)");
    return false;
  }
  const size_t n = data->dims[0];
  if (data->dims[1] != cols) {
    text::SetError(e, path, 0, 0,
                   what + "is " + std::to_string(data->dims[0]) + " x " +
                       std::to_string(data->dims[1]) + ", expected N x " + std::to_string(cols) +
                       " (one column per name in '" + names_var + "')");
    return false;
  }
  if (n == 0) {
    text::SetError(e, path, 0, 0, what + "empty stream: no rows");
    return false;
  }
  const LabTopic& topic = *table->header.topic;
  // An int64 matrix (pandas' type for a file of integers) keeps its stamps exact.
  const bool int64_stamps = data->data_type == MAT_T_INT64;
  for (size_t i = 0; i < n; ++i) {
    const int row = text::ToInt(i + 1);
    const double t = v[i];  // column-major: column 0 is the first n elements
    // 9.2e18 ns is the int64 limit (the year 2262).
    if (!std::isfinite(t) || t < 0 || t >= 9.2e18 || t != std::floor(t)) {
      text::SetError(e, path, row, 1,
                     what + "time stamp " + text::FormatDouble(t) +
                         " is not a non-negative integer number of ns");
      return false;
    }
    const long long stamp =
        int64_stamps ? static_cast<const int64_t*>(data->data)[i] : static_cast<long long>(t);
    if (!table->t_ns.empty() && stamp <= table->t_ns.back()) {
      text::SetError(e, path, row, 1,
                     what + (stamp == table->t_ns.back() ? "duplicate" : "non-monotonic") +
                         " time stamp " + std::to_string(stamp) + " ns");
      return false;
    }
    std::vector<double> values(topic.size(), 0.0);
    if (topic.id == StreamId::kPressure && !table->header.has_ch) values[0] = 4;
    for (size_t c = 1; c < cols; ++c) {
      const int field = table->header.field_of_column[c - 1];
      const double x = v[c * n + i];
      if (!std::isfinite(x)) {
        text::SetError(
            e, path, row, text::ToInt(c + 1),
            what + "non-finite value (" + topic.short_names[static_cast<size_t>(field)] + ")");
        return false;
      }
      values[static_cast<size_t>(field)] = x;
    }
    table->t_ns.push_back(stamp);
    table->rows.push_back(std::move(values));
    table->lines.push_back(row);
  }
  return true;
}

// A numeric argument: a scalar or a row/column vector.
bool ReadNumbers(mat_t* mat, const std::string& path, const char* name, size_t min_n, size_t max_n,
                 std::vector<double>* out, LoadError* e) {
  VarPtr v(Mat_VarRead(mat, name));
  out->clear();
  if (!v) return true;  // absent: not a disk benchmark file
  std::vector<double> values;
  const size_t n = Elements(v.get());
  if (!ToDoubles(v.get(), &values) || n < min_n || n > max_n) {
    text::SetError(e, path, 0, 0,
                   std::string("variable '") + name + "': expected " +
                       (min_n == max_n ? std::to_string(min_n)
                                       : std::to_string(min_n) + " to " + std::to_string(max_n)) +
                       " finite number(s)");
    return false;
  }
  for (double x : values) {
    if (!std::isfinite(x)) {
      text::SetError(e, path, 0, 0, std::string("variable '") + name + "': non-finite value");
      return false;
    }
  }
  *out = values;
  return true;
}

bool ReadScalar(mat_t* mat, const std::string& path, const char* name, double* out, LoadError* e) {
  std::vector<double> v;
  if (!ReadNumbers(mat, path, name, 1, 1, &v, e)) return false;
  if (!v.empty()) *out = v[0];
  return true;
}

// edgeFollowing_history: an N x 11 cell array (what savemat makes of rows holding 2-vectors),
// an N x 11 numeric matrix (scalar r_p...) or an N x 14 one (the vectors spread out).
bool ReadHistory(mat_t* mat, const std::string& path, std::vector<HistoryRow>* out, LoadError* e) {
  constexpr char kName[] = "edgeFollowing_history";
  VarPtr v(Mat_VarRead(mat, kName));
  if (!v) return true;
  const std::string what = std::string("variable '") + kName + "': ";
  if (v->rank != 2) {
    text::SetError(e, path, 0, 0, what + "expected an N x 11 matrix or cell array");
    return false;
  }
  const size_t n = v->dims[0], cols = v->dims[1];
  // Each row as a flat list of numbers: t, x, y, r_p(1-2), corr_p(1-2), r_p_final(1-2), F, P1..P4.
  std::vector<std::vector<double>> rows(n);
  if (v->class_type == MAT_C_CELL) {
    if (cols != kHistoryColumns) {
      text::SetError(e, path, 0, 0,
                     what + "is a " + std::to_string(n) + " x " + std::to_string(cols) +
                         " cell array, expected N x 11");
      return false;
    }
    for (size_t i = 0; i < n; ++i) {
      for (size_t c = 0; c < cols; ++c) {
        matvar_t* cell = Mat_VarGetCell(v.get(), static_cast<int>(c * n + i));
        std::vector<double> x;
        const size_t want = (c >= 3 && c <= 5) ? 2 : 1;
        if (cell == nullptr || !ToDoubles(cell, &x) || (x.size() != 1 && x.size() != want)) {
          text::SetError(e, path, text::ToInt(i + 1), text::ToInt(c + 1),
                         what + "cell is not " + (want == 2 ? "a 2-vector or " : "") + "a number");
          return false;
        }
        if (x.size() == 1 && want == 2) x.push_back(0.0);
        rows[i].insert(rows[i].end(), x.begin(), x.end());
      }
    }
  } else {
    std::vector<double> x;
    if (!ToDoubles(v.get(), &x) || (cols != kHistoryColumns && cols != kHistoryRowNumbers)) {
      text::SetError(e, path, 0, 0,
                     what + "is " + std::to_string(n) + " x " + std::to_string(cols) +
                         ", expected an N x 11 cell array or an N x 14 matrix");
      return false;
    }
    for (size_t i = 0; i < n; ++i) {
      for (size_t c = 0; c < cols; ++c) {
        rows[i].push_back(x[c * n + i]);
        if (cols == kHistoryColumns && c >= 3 && c <= 5) rows[i].push_back(0.0);
      }
    }
  }
  for (size_t i = 0; i < n; ++i) {
    const std::vector<double>& r = rows[i];  // kHistoryRowNumbers
    for (size_t k = 0; k < r.size(); ++k) {
      if (!std::isfinite(r[k])) {
        text::SetError(e, path, text::ToInt(i + 1), 0, what + "non-finite value");
        return false;
      }
    }
    const HistoryRow h = HistoryRowFromNumbers(r.data());
    if (!out->empty() && !(h.t_s > out->back().t_s)) {
      text::SetError(e, path, text::ToInt(i + 1), 1,
                     what + "time " + text::FormatDouble(h.t_s) + " s does not increase (row " +
                         std::to_string(i) + ": " + text::FormatDouble(out->back().t_s) + " s)");
      return false;
    }
    out->push_back(h);
  }
  return true;
}

bool ReadArgs(mat_t* mat, const std::string& path, LabRunArgs* a, LoadError* e) {
  return ReadScalar(mat, path, "Pref", &a->p_ref_pa, e) &&
         ReadScalar(mat, path, "beta", &a->beta, e) &&
         ReadScalar(mat, path, "d_lat", &a->d_lat_m, e) &&
         ReadScalar(mat, path, "diskRadius", &a->disk_radius_mm, e) &&
         ReadScalar(mat, path, "start_offset", &a->start_offset_m, e) &&
         ReadScalar(mat, path, "success", &a->success, e) &&
         ReadNumbers(mat, path, "P_lims", 2, 2, &a->p_lims_pa, e) &&
         ReadNumbers(mat, path, "alpha_beta", 4, 4, &a->alpha_beta, e) &&
         ReadNumbers(mat, path, "Fz_set", 1, 2, &a->fz_set_n, e) &&
         ReadHistory(mat, path, &a->history, e);
}

// --- writing ---

bool WriteVar(mat_t* mat, matvar_t* v, const std::string& name, std::string* error) {
  VarPtr owned(v);
  if (!owned || Mat_VarWrite(mat, owned.get(), MAT_COMPRESSION_NONE) != 0) {
    *error = "cannot write variable '" + name + "'";
    return false;
  }
  return true;
}

matvar_t* Doubles(const char* name, size_t rows, size_t cols, const std::vector<double>& v) {
  size_t dims[2] = {rows, cols};
  return Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, const_cast<double*>(v.data()), 0);
}

matvar_t* Int64s(const char* name, size_t rows, size_t cols, const std::vector<double>& v) {
  std::vector<int64_t> x(v.size());
  for (size_t i = 0; i < v.size(); ++i) x[i] = std::llround(v[i]);
  size_t dims[2] = {rows, cols};
  return Mat_VarCreate(name, MAT_C_INT64, MAT_T_INT64, 2, dims, x.data(), 0);
}

matvar_t* CharMatrix(const std::string& name, const std::vector<std::string>& rows) {
  size_t len = 0;
  for (const std::string& r : rows) len = std::max(len, r.size());
  std::vector<char> data(rows.size() * len, ' ');  // space-padded, column-major
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t c = 0; c < rows[r].size(); ++c) data[c * rows.size() + r] = rows[r][c];
  }
  size_t dims[2] = {rows.size(), len};
  return Mat_VarCreate(name.c_str(), MAT_C_CHAR, MAT_T_UINT8, 2, dims, data.data(), 0);
}

// The header names as the logger of `version` writes them, as pandas then names them.
std::vector<std::string> ColumnNames(const LabTopic& t, LoggerVersion version) {
  std::vector<std::string> names = {"ROStimestamp"};
  for (size_t f = 0; f < t.size(); ++f) {
    std::string field = t.fields[f];
    if (version == LoggerVersion::kOlder) {
      if (t.id == StreamId::kPressure && field == "ch") continue;
      const size_t bracket = field.find('[');
      if (bracket != std::string::npos) {
        const int k = std::atoi(field.c_str() + bracket + 1);
        field.resize(bracket);
        if (k > 0) field += "." + std::to_string(k);
      }
    }
    names.push_back(t.topic + "." + field);
  }
  return names;
}

bool WriteStream(mat_t* mat, const LabTopic& t, LoggerVersion version, long long t0_ns,
                 const Stream& s, std::string* error) {
  const std::vector<std::string> names = ColumnNames(t, version);
  const size_t n = s.size(), cols = names.size();
  const bool skip_ch = version == LoggerVersion::kOlder && t.id == StreamId::kPressure;
  std::vector<double> data(n * cols);
  bool integers = true;
  for (size_t i = 0; i < n; ++i) {
    if (s.rows[i].size() != t.size()) {
      *error = t.mat_name + ": row " + std::to_string(i + 1) + " has " +
               std::to_string(s.rows[i].size()) + " fields, the topic has " +
               std::to_string(t.size());
      return false;
    }
    data[i] = static_cast<double>(t0_ns + std::llround(s.t_s[i] * 1e9));
    size_t c = 1;
    for (size_t f = skip_ch ? 1 : 0; f < t.size(); ++f, ++c) {
      double v = s.rows[i][f];
      if (t.id == StreamId::kPressure && f > 0) v = static_cast<float>(v);  // float32[] data
      if (t.id == StreamId::kPwm || (t.id == StreamId::kPressure && f == 0)) v = std::round(v);
      integers = integers && v == std::floor(v);
      data[c * n + i] = v;
    }
  }
  const std::string data_name = t.mat_name + kDataSuffix;
  matvar_t* v = nullptr;
  if (t.id == StreamId::kPwm && integers) {
    // pandas keeps a file of integers (the PWM's) as int64: its stamps stay exact.
    std::vector<int64_t> x(data.size());
    for (size_t i = 0; i < data.size(); ++i) x[i] = std::llround(data[i]);
    for (size_t i = 0; i < n; ++i) x[i] = t0_ns + std::llround(s.t_s[i] * 1e9);
    size_t dims[2] = {n, cols};
    v = Mat_VarCreate(data_name.c_str(), MAT_C_INT64, MAT_T_INT64, 2, dims, x.data(), 0);
  } else {
    v = Doubles(data_name.c_str(), n, cols, data);
  }
  return WriteVar(mat, v, data_name, error) &&
         WriteVar(mat, CharMatrix(t.mat_name + kColumnSuffix, names), t.mat_name + kColumnSuffix,
                  error);
}

bool WriteHistory(mat_t* mat, const std::vector<HistoryRow>& history, std::string* error) {
  const size_t n = history.size();
  size_t dims[2] = {n, kHistoryColumns};
  matvar_t* cell =
      Mat_VarCreate("edgeFollowing_history", MAT_C_CELL, MAT_T_CELL, 2, dims, nullptr, 0);
  if (cell == nullptr) {
    *error = "cannot create edgeFollowing_history";
    return false;
  }
  for (size_t i = 0; i < n; ++i) {
    const HistoryRow& h = history[i];
    const std::vector<std::vector<double>> row = {{h.t_s},
                                                  {h.x_m},
                                                  {h.y_m},
                                                  {h.r_p[0], h.r_p[1]},
                                                  {h.corr_p[0], h.corr_p[1]},
                                                  {h.r_p_final[0], h.r_p_final[1]},
                                                  {h.f_normal_n},
                                                  {h.p_pa[0]},
                                                  {h.p_pa[1]},
                                                  {h.p_pa[2]},
                                                  {h.p_pa[3]}};
    for (size_t c = 0; c < kHistoryColumns; ++c) {
      Mat_VarSetCell(cell, static_cast<int>(c * n + i), Doubles(nullptr, 1, row[c].size(), row[c]));
    }
  }
  return WriteVar(mat, cell, "edgeFollowing_history", error);
}

bool WriteArgs(mat_t* mat, const LabRunArgs& a, std::string* error) {
  auto scalar = [&](const char* name, double v, bool integer) {
    if (std::isnan(v)) return true;
    const std::vector<double> x = {v};
    return WriteVar(mat, integer ? Int64s(name, 1, 1, x) : Doubles(name, 1, 1, x), name, error);
  };
  auto vec = [&](const char* name, const std::vector<double>& v, bool integer) {
    if (v.empty()) return true;
    return WriteVar(mat, integer ? Int64s(name, 1, v.size(), v) : Doubles(name, 1, v.size(), v),
                    name, error);
  };
  // The script's types: P_ref, diskRadius, P_lims and success are Python ints.
  return scalar("d_lat", a.d_lat_m, false) && scalar("diskRadius", a.disk_radius_mm, true) &&
         scalar("start_offset", a.start_offset_m, false) && vec("P_lims", a.p_lims_pa, true) &&
         vec("alpha_beta", a.alpha_beta, false) && scalar("Pref", a.p_ref_pa, true) &&
         scalar("beta", a.beta, false) && scalar("success", a.success, true) &&
         (a.history.empty() || WriteHistory(mat, a.history, error)) &&
         vec("Fz_set", a.fz_set_n, false);
}

}  // namespace

bool LoadRobotLogMat(const std::string& path, RobotLog* log, LoadError* error) {
  try {
    *log = RobotLog();
    if (!text::CheckReadableFile(path, error) || !CheckMat5Complete(path, error)) return false;
    MatPtr mat(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
    if (!mat) {
      text::SetError(error, path, 0, 0, "not a MATLAB file matio can open (v4, v5 or v7.3)");
      return false;
    }
    const std::vector<LabTopic>& topics = LabTopics();
    std::vector<TopicTable> tables(topics.size());
    std::vector<std::string> prefixes(topics.size());
    long long t0 = -1;
    for (const std::string& name : VariableNames(mat.get())) {
      if (!EndsWith(name, kColumnSuffix)) continue;
      const std::string prefix = name.substr(0, name.size() - sizeof(kColumnSuffix) + 1);
      TopicTable table;
      if (!ReadTopicPair(mat.get(), path, prefix, &table, error)) return false;
      if (table.header.topic == nullptr) continue;
      const size_t i = static_cast<size_t>(table.header.topic->id);
      if (!prefixes[i].empty()) {
        text::SetError(error, path, 0, 0,
                       "variables '" + prefixes[i] + kDataSuffix + "' and '" + prefix +
                           kDataSuffix + "' both hold topic " + topics[i].topic);
        return false;
      }
      prefixes[i] = prefix;
      t0 = t0 < 0 ? table.t_ns.front() : std::min(t0, table.t_ns.front());
      tables[i] = std::move(table);
    }
    for (size_t i = 0; i < topics.size(); ++i) {
      if (!topics[i].required || !prefixes[i].empty()) continue;
      text::SetError(error, path, 0, 0,
                     "no variable holds topic " + topics[i].topic + " (a required stream; the " +
                         "saver writes it as " + topics[i].mat_name + kDataSuffix + " with " +
                         topics[i].mat_name + kColumnSuffix + ")");
      return false;
    }
    if (!ReadArgs(mat.get(), path, &log->args, error)) return false;
    log->t0_ns = t0;
    log->origin = path;
    Stream* streams[] = {&log->pressure_abs, &log->tool_pose, &log->ft, &log->pwm};
    for (size_t i = 0; i < topics.size(); ++i) {
      if (prefixes[i].empty()) continue;
      Stream& s = *streams[i];
      s.source = path;
      s.variable = prefixes[i] + kDataSuffix;
      for (long long t : tables[i].t_ns) s.t_s.push_back(static_cast<double>(t - t0) * 1e-9);
      s.rows = std::move(tables[i].rows);
      s.lines = std::move(tables[i].lines);
    }
    return CheckRosEpoch(*log, error) && ValidateRobotLog(*log, error);
  } catch (const std::exception& ex) {
    text::SetError(error, path, 0, 0, std::string("cannot load: ") + ex.what());
    return false;
  }
}

bool WriteRobotLogMat(const std::string& path, const RobotLog& log, std::string* error,
                      LoggerVersion version, MatVersion mat_version) {
  try {
    MatPtr mat(Mat_CreateVer(path.c_str(), nullptr,
                             mat_version == MatVersion::kMat73 ? MAT_FT_MAT73 : MAT_FT_MAT5));
    if (!mat) {
      *error = path + ": cannot create the MATLAB file" +
               (mat_version == MatVersion::kMat73 ? " (v7.3 needs matio built with HDF5)" : "");
      return false;
    }
    const Stream* streams[] = {&log.pressure_abs, &log.tool_pose, &log.ft, &log.pwm};
    for (const LabTopic& t : LabTopics()) {
      const Stream& s = *streams[static_cast<size_t>(t.id)];
      if (s.empty()) continue;
      if (!WriteStream(mat.get(), t, version, log.t0_ns, s, error)) {
        *error = path + ": " + *error;
        return false;
      }
    }
    if (!WriteArgs(mat.get(), log.args, error)) {
      *error = path + ": " + *error;
      return false;
    }
    return true;
  } catch (const std::exception& ex) {
    *error = path + ": " + ex.what();
    return false;
  }
}

std::string DiskBenchmarkMatName(const std::string& stamp, const LabRunArgs& a) {
  auto py = [](double v, bool integer) {
    return integer ? std::to_string(std::llround(v)) : text::PyFloat(v);
  };
  return "DataLog_" + stamp + "_seb_testEdgeFollowing_refP_" + py(a.p_ref_pa, true) + "_beta_" +
         py(a.beta, false) + "_step_" + py(a.d_lat_m, false) + "_deleteMe.mat";
}

}  // namespace ssc
