// The merged MATLAB log, through matio (never a hand-written MAT parser).
#include <matio.h>

#include <cmath>
#include <string>

#include "robotlog/robot_log.h"

namespace ssc {
namespace {

struct MatFile {
  mat_t* mat = nullptr;
  ~MatFile() {
    if (mat) Mat_Close(mat);
  }
};

// Reads variable `name` (a real double matrix with n_cols columns, time in ns first).
bool ReadMatrix(mat_t* mat, const std::string& path, const char* name, size_t n_cols,
                bool required, std::vector<long long>* t_ns, std::vector<std::vector<double>>* rows,
                LoadError* e) {
  matvar_t* v = Mat_VarRead(mat, name);
  if (v == nullptr) {
    if (!required) return true;
    *e = {path, 0, 0, std::string("variable '") + name + "' is missing"};
    return false;
  }
  bool ok = v->class_type == MAT_C_DOUBLE && v->data_type == MAT_T_DOUBLE && v->rank == 2 &&
            v->isComplex == 0 && v->dims[1] == n_cols && v->dims[0] > 0;
  if (!ok) {
    *e = {path, 0, 0, std::string("variable '") + name + "' must be a real double matrix with " +
                          std::to_string(n_cols) + " columns (time in ns, then the fields)"};
    Mat_VarFree(v);
    return false;
  }
  const size_t n = v->dims[0];
  const double* data = static_cast<const double*>(v->data);  // column-major
  for (size_t i = 0; i < n && ok; ++i) {
    const double t = data[i];
    if (!std::isfinite(t) || (!t_ns->empty() && static_cast<long long>(t) <= t_ns->back())) {
      *e = {path, static_cast<int>(i + 1), 1,
            std::string(name) + ": non-finite, duplicate or non-monotonic time"};
      ok = false;
      break;
    }
    std::vector<double> row(n_cols - 1);
    for (size_t c = 1; c < n_cols; ++c) {
      row[c - 1] = data[c * n + i];
      if (!std::isfinite(row[c - 1])) {
        *e = {path, static_cast<int>(i + 1), static_cast<int>(c + 1),
              std::string(name) + ": non-finite value"};
        ok = false;
        break;
      }
    }
    t_ns->push_back(static_cast<long long>(t));
    rows->push_back(std::move(row));
  }
  Mat_VarFree(v);
  return ok;
}

bool WriteMatrix(mat_t* mat, const char* name, const RobotLog& log, const Stream& s) {
  if (s.empty()) return true;
  const size_t n = s.t_s.size(), cols = s.rows.front().size() + 1;
  std::vector<double> data(n * cols);
  for (size_t i = 0; i < n; ++i) {
    data[i] = static_cast<double>(log.t0_ns + std::llround(s.t_s[i] * 1e9));
    for (size_t c = 1; c < cols; ++c) data[c * n + i] = s.rows[i][c - 1];
  }
  size_t dims[2] = {n, cols};
  matvar_t* v = Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, data.data(), 0);
  if (v == nullptr) return false;
  const bool ok = Mat_VarWrite(mat, v, MAT_COMPRESSION_NONE) == 0;
  Mat_VarFree(v);
  return ok;
}

}  // namespace

bool LoadRobotLogMat(const std::string& path, RobotLog* log, LoadError* e) {
  MatFile f;
  f.mat = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
  if (f.mat == nullptr) {
    *e = {path, 0, 0, "cannot open as a MATLAB file"};
    return false;
  }
  struct Var {
    const char* name;
    size_t cols;
    Stream* stream;
    bool required;
  } vars[4] = {{"pressure", 6, &log->pressure_abs, true},
               {"tool_pose", 8, &log->tool_pose, true},
               {"ft", 7, &log->ft, false},
               {"pwm", 2, &log->pwm, false}};
  std::vector<long long> t[4];
  std::vector<std::vector<double>> rows[4];
  long long t0 = -1;
  for (int i = 0; i < 4; ++i) {
    if (!ReadMatrix(f.mat, path, vars[i].name, vars[i].cols, vars[i].required, &t[i], &rows[i], e))
      return false;
    if (!t[i].empty()) t0 = t0 < 0 ? t[i].front() : std::min(t0, t[i].front());
  }
  log->t0_ns = t0;
  for (int i = 0; i < 4; ++i) {
    if (t[i].empty()) continue;
    vars[i].stream->t_s.clear();
    for (long long ti : t[i]) vars[i].stream->t_s.push_back(static_cast<double>(ti - t0) * 1e-9);
    vars[i].stream->rows = std::move(rows[i]);
  }
  for (size_t i = 0; i < log->pressure_abs.rows.size(); ++i) {
    for (int c = 1; c <= 4; ++c) {
      const double p = log->pressure_abs.rows[i][c];
      if (p < 30000 || p > 130000) {
        *e = {path, static_cast<int>(i + 1), c + 2,
              "pressure: " + std::to_string(p) + " Pa is not an absolute pressure (30-130 kPa)"};
        return false;
      }
    }
  }
  return true;
}

bool WriteRobotLogMat(const std::string& path, const RobotLog& log, std::string* error) {
  MatFile f;
  f.mat = Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5);
  if (f.mat == nullptr) {
    *error = path + ": cannot create";
    return false;
  }
  if (!WriteMatrix(f.mat, "pressure", log, log.pressure_abs) ||
      !WriteMatrix(f.mat, "tool_pose", log, log.tool_pose) || !WriteMatrix(f.mat, "ft", log, log.ft) ||
      !WriteMatrix(f.mat, "pwm", log, log.pwm)) {
    *error = path + ": write failed";
    return false;
  }
  return true;
}

}  // namespace ssc
