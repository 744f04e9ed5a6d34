#include "robotlog/mat_log.h"

#include <matio.h>

#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "robotlog/robot_log.h"
#include "robotlog/text_cells.h"

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

template <typename T>
void Convert(const void* data, size_t n, std::vector<double>* out) {
  const T* p = static_cast<const T*>(data);
  out->resize(n);
  for (size_t i = 0; i < n; ++i) (*out)[i] = static_cast<double>(p[i]);
}

// The variable's elements as doubles (column-major); false for a type we cannot convert.
bool ToDoubles(const matvar_t* v, size_t n, std::vector<double>* out) {
  switch (v->data_type) {
    case MAT_T_DOUBLE: Convert<double>(v->data, n, out); return true;
    case MAT_T_SINGLE: Convert<float>(v->data, n, out); return true;
    case MAT_T_INT8: Convert<int8_t>(v->data, n, out); return true;
    case MAT_T_UINT8: Convert<uint8_t>(v->data, n, out); return true;
    case MAT_T_INT16: Convert<int16_t>(v->data, n, out); return true;
    case MAT_T_UINT16: Convert<uint16_t>(v->data, n, out); return true;
    case MAT_T_INT32: Convert<int32_t>(v->data, n, out); return true;
    case MAT_T_UINT32: Convert<uint32_t>(v->data, n, out); return true;
    case MAT_T_INT64: Convert<int64_t>(v->data, n, out); return true;
    case MAT_T_UINT64: Convert<uint64_t>(v->data, n, out); return true;
    default: return false;
  }
}

bool IsNumericClass(matio_classes c) {
  return c >= MAT_C_DOUBLE && c <= MAT_C_UINT64;
}

// Reads one stream's matrix into `t_ns` and `rows`; `found` tells whether it was there.
bool ReadStream(mat_t* mat, const std::string& path, const StreamSpec& spec, std::string* name,
                std::vector<long long>* t_ns, std::vector<std::vector<double>>* rows,
                LoadError* e) {
  VarPtr v;
  for (const std::string& candidate : spec.variables) {
    VarPtr found(Mat_VarRead(mat, candidate.c_str()));
    if (!found) continue;
    if (v) {
      text::SetError(e, path, 0, 0, "both '" + *name + "' and '" + candidate +
                                        "' hold the same stream; keep one");
      return false;
    }
    v = std::move(found);
    *name = candidate;
  }
  if (!v) {
    if (spec.required) {
      text::SetError(e, path, 0, 0, "variable '" + spec.variables.front() + "' is missing (a " +
                                        "required stream)");
      return false;
    }
    return true;
  }
  const size_t cols = spec.fields() + 1;
  const std::string what = "variable '" + *name + "': ";
  if (!IsNumericClass(v->class_type) || v->isComplex) {
    text::SetError(e, path, 0, 0, what + "must be a real numeric matrix (time in ns, then " +
                                      std::to_string(spec.fields()) + " fields)");
    return false;
  }
  if (v->rank != 2) {
    text::SetError(e, path, 0, 0, what + "has " + std::to_string(v->rank) +
                                      " dimensions, expected a matrix");
    return false;
  }
  const size_t n = v->dims[0];
  if (v->dims[1] != cols) {
    const bool transposed = v->dims[0] == cols;
    text::SetError(e, path, 0, 0, what + "is " + std::to_string(v->dims[0]) + " x " +
                                      std::to_string(v->dims[1]) + ", expected N x " +
                                      std::to_string(cols) +
                                      (transposed ? " (transpose it: one row per sample)" : ""));
    return false;
  }
  if (n == 0) {
    text::SetError(e, path, 0, 0, what + "empty stream: no rows");
    return false;
  }
  std::vector<double> data;
  if (v->data == nullptr || !ToDoubles(v.get(), n * cols, &data)) {
    text::SetError(e, path, 0, 0, what + "unsupported element type");
    return false;
  }
  for (size_t i = 0; i < n; ++i) {
    const int row = text::ToInt(i + 1);
    const double t = data[i];  // column-major: column 0 is the first n elements
    // 9.2e18 ns is the int64 limit (the year 2262).
    if (!std::isfinite(t) || t < 0 || t >= 9.2e18 || t != std::floor(t)) {
      text::SetError(e, path, row, 1, what + "time stamp " + text::FormatDouble(t) +
                                          " is not a non-negative integer number of ns");
      return false;
    }
    const long long stamp = static_cast<long long>(t);
    if (!t_ns->empty() && stamp <= t_ns->back()) {
      text::SetError(e, path, row, 1,
                     what + (stamp == t_ns->back() ? "duplicate" : "non-monotonic") +
                         " time stamp " + std::to_string(stamp) + " ns");
      return false;
    }
    std::vector<double> values(spec.fields());
    for (size_t c = 1; c < cols; ++c) {
      values[c - 1] = data[c * n + i];
      if (!std::isfinite(values[c - 1])) {
        text::SetError(e, path, row, text::ToInt(c + 1),
                       what + "non-finite value (" + spec.columns[c - 1].front() + ")");
        return false;
      }
    }
    t_ns->push_back(stamp);
    rows->push_back(std::move(values));
  }
  return true;
}

bool WriteStream(mat_t* mat, const std::string& name, long long t0_ns, const Stream& s,
                 size_t fields, std::string* error) {
  const size_t n = s.size(), cols = fields + 1;
  std::vector<double> data(n * cols);
  for (size_t i = 0; i < n; ++i) {
    if (s.rows[i].size() != fields) {
      *error = name + ": row " + std::to_string(i + 1) + " has " +
               std::to_string(s.rows[i].size()) + " fields, the stream has " +
               std::to_string(fields);
      return false;
    }
    data[i] = static_cast<double>(t0_ns + std::llround(s.t_s[i] * 1e9));
    for (size_t c = 1; c < cols; ++c) data[c * n + i] = s.rows[i][c - 1];
  }
  size_t dims[2] = {n, cols};
  VarPtr v(Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, data.data(), 0));
  if (!v || Mat_VarWrite(mat, v.get(), MAT_COMPRESSION_NONE) != 0) {
    *error = "cannot write variable '" + name + "'";
    return false;
  }
  return true;
}

}  // namespace

bool LoadRobotLogMat(const std::string& path, RobotLog* log, LoadError* error) {
  try {
    *log = RobotLog();
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      text::SetError(error, path, 0, 0, "no such file");
      return false;
    }
    if (fs::is_directory(path, ec)) {
      text::SetError(error, path, 0, 0, "is a directory, expected a .mat file");
      return false;
    }
    MatPtr mat(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
    if (!mat) {
      text::SetError(error, path, 0, 0, "not a MATLAB file matio can open (v4, v5 or v7.3)");
      return false;
    }
    const std::vector<StreamSpec>& specs = AllStreamSpecs();
    Stream* streams[] = {&log->pressure_abs, &log->tool_pose, &log->ft, &log->pwm};
    std::vector<std::vector<long long>> t(specs.size());
    std::vector<std::vector<std::vector<double>>> rows(specs.size());
    std::vector<std::string> names(specs.size());
    long long t0 = -1;
    for (size_t i = 0; i < specs.size(); ++i) {
      if (!ReadStream(mat.get(), path, specs[i], &names[i], &t[i], &rows[i], error)) return false;
      if (!t[i].empty()) t0 = t0 < 0 ? t[i].front() : std::min(t0, t[i].front());
    }
    log->t0_ns = t0;
    for (size_t i = 0; i < specs.size(); ++i) {
      if (t[i].empty()) continue;
      Stream& s = *streams[i];
      s.source = path;
      s.variable = names[i];
      for (size_t k = 0; k < t[i].size(); ++k) {
        s.t_s.push_back(static_cast<double>(t[i][k] - t0) * 1e-9);
        s.lines.push_back(text::ToInt(k + 1));
      }
      s.rows = std::move(rows[i]);
    }
    return ValidateRobotLog(*log, error);
  } catch (const std::exception& ex) {
    text::SetError(error, path, 0, 0, std::string("cannot load: ") + ex.what());
    return false;
  }
}

bool WriteRobotLogMat(const std::string& path, const RobotLog& log, std::string* error,
                      MatVersion version) {
  try {
    MatPtr mat(Mat_CreateVer(path.c_str(), nullptr,
                             version == MatVersion::kMat73 ? MAT_FT_MAT73 : MAT_FT_MAT5));
    if (!mat) {
      *error = path + ": cannot create the MATLAB file" +
               (version == MatVersion::kMat73 ? " (v7.3 needs matio built with HDF5)" : "");
      return false;
    }
    const Stream* streams[] = {&log.pressure_abs, &log.tool_pose, &log.ft, &log.pwm};
    for (const StreamSpec& spec : AllStreamSpecs()) {
      const Stream& s = *streams[static_cast<size_t>(spec.id)];
      if (s.empty()) continue;
      if (!WriteStream(mat.get(), spec.variables.front(), log.t0_ns, s, spec.fields(), error)) {
        *error = path + ": " + *error;
        return false;
      }
    }
    return true;
  } catch (const std::exception& ex) {
    *error = path + ": " + ex.what();
    return false;
  }
}

}  // namespace ssc
