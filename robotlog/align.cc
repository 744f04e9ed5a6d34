#include "robotlog/align.h"

#include <algorithm>
#include <cmath>

namespace ssc {
namespace {

// Bracket of time t in the stream: i0 <= i1 and the fraction u in [0, 1] from i0 to i1.
struct Bracket {
  size_t i0 = 0, i1 = 0;
  double u = 0;
};

Bracket Find(const std::vector<double>& t, double time, Interpolation mode) {
  Bracket b;
  if (t.empty() || time <= t.front()) return b;
  if (time >= t.back()) {
    b.i0 = b.i1 = t.size() - 1;
    return b;
  }
  // First sample after `time`: 1 <= i1 < size.
  const size_t i1 = static_cast<size_t>(std::upper_bound(t.begin(), t.end(), time) - t.begin());
  b.i0 = i1 - 1;
  if (mode == Interpolation::kZeroOrderHold) {
    b.i1 = b.i0;
    return b;
  }
  b.i1 = i1;
  b.u = (time - t[b.i0]) / (t[i1] - t[b.i0]);
  return b;
}

Eigen::Quaterniond QuatFromRow(const std::vector<double>& row) {
  Eigen::Quaterniond q(row[0], row[1], row[2], row[3]);
  const double n = q.norm();
  if (n > 0) {
    q.coeffs() /= n;
  } else {
    q.setIdentity();
  }
  return q;
}

}  // namespace

std::vector<std::vector<double>> ResampleRows(const Stream& in, const std::vector<double>& t_s,
                                              Interpolation mode) {
  std::vector<std::vector<double>> out;
  if (in.empty()) return out;
  out.reserve(t_s.size());
  for (double t : t_s) {
    const Bracket b = Find(in.t_s, t, mode);
    const std::vector<double>& a = in.rows[b.i0];
    const std::vector<double>& c = in.rows[b.i1];
    std::vector<double> row(a.size());
    for (size_t k = 0; k < a.size() && k < c.size(); ++k) row[k] = a[k] + b.u * (c[k] - a[k]);
    out.push_back(std::move(row));
  }
  return out;
}

std::vector<Eigen::Isometry3d> ResamplePose(const Stream& pose, const std::vector<double>& t_s,
                                            Interpolation mode,
                                            std::vector<Eigen::Quaterniond>* quats) {
  std::vector<Eigen::Isometry3d> out;
  if (quats) quats->clear();
  if (pose.empty()) return out;
  out.reserve(t_s.size());
  for (double t : t_s) {
    const Bracket b = Find(pose.t_s, t, mode);
    const std::vector<double>& a = pose.rows[b.i0];
    const std::vector<double>& c = pose.rows[b.i1];
    const Eigen::Quaterniond q = QuatFromRow(a).slerp(b.u, QuatFromRow(c)).normalized();
    if (quats) quats->push_back(q);
    const Eigen::Vector3d pa(a[4], a[5], a[6]), pc(c[4], c[5], c[6]);
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.linear() = q.toRotationMatrix();
    X.translation() = pa + b.u * (pc - pa);
    out.push_back(X);
  }
  return out;
}

std::vector<double> UniformClock(double begin_s, double end_s, double rate_hz) {
  std::vector<double> t;
  if (!(rate_hz > 0) || !(end_s >= begin_s)) return t;
  const double n = std::floor((end_s - begin_s) * rate_hz + 1e-9 * rate_hz);
  if (!(n < 1e8)) return t;  // refuse absurd clocks rather than exhaust memory
  for (long k = 0; k <= static_cast<long>(n); ++k) {
    t.push_back(begin_s + static_cast<double>(k) / rate_hz);
  }
  return t;
}

int InAirOffset(const Stream& pressure_abs, double begin_s, double end_s,
                std::array<double, 4>* offset_pa) {
  std::array<double, 4> sum{};
  int n = 0;
  for (size_t i = 0; i < pressure_abs.size(); ++i) {
    const double t = pressure_abs.t_s[i];
    if (t < begin_s || t >= end_s) continue;
    for (int c = 0; c < 4; ++c) sum[c] += pressure_abs.rows[i][c + 1];
    ++n;
  }
  if (n == 0) return 0;
  for (int c = 0; c < 4; ++c) (*offset_pa)[c] = sum[c] / n;
  return n;
}

std::vector<std::array<double, 4>> GaugeVacuum(const Stream& pressure_abs,
                                               const std::array<double, 4>& offset_pa) {
  std::vector<std::array<double, 4>> out(pressure_abs.size());
  for (size_t i = 0; i < out.size(); ++i) {
    for (int c = 0; c < 4; ++c) out[i][c] = offset_pa[c] - pressure_abs.rows[i][c + 1];
  }
  return out;
}

std::vector<std::array<double, 4>> MovingAverage(const std::vector<std::array<double, 4>>& x,
                                                 int window) {
  if (window <= 1) return x;
  const size_t w = static_cast<size_t>(window);
  std::vector<std::array<double, 4>> out(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    // Summed afresh per sample: a running sum would drift over long logs.
    const size_t from = i + 1 >= w ? i + 1 - w : 0;
    std::array<double, 4> sum{};
    for (size_t k = from; k <= i; ++k) {
      for (int c = 0; c < 4; ++c) sum[c] += x[k][c];
    }
    for (int c = 0; c < 4; ++c) out[i][c] = sum[c] / static_cast<double>(i - from + 1);
  }
  return out;
}

Eigen::Isometry3d PoseFromRow(const std::vector<double>& row) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = QuatFromRow(row).toRotationMatrix();
  X.translation() = Eigen::Vector3d(row[4], row[5], row[6]);
  return X;
}

Eigen::Vector3d TcpFromTool0(const Eigen::Isometry3d& X_frame_tool0, double tcp_offset_m) {
  return X_frame_tool0 * Eigen::Vector3d(0, 0, tcp_offset_m);
}

Eigen::Vector3d Tool0FromTcp(const Eigen::Vector3d& tcp, const Eigen::Quaterniond& q_frame_tool0,
                             double tcp_offset_m) {
  return tcp - q_frame_tool0.normalized() * Eigen::Vector3d(0, 0, tcp_offset_m);
}

void TransformProcessedLog(const Eigen::Isometry3d& X_new_old, ProcessedLog* log) {
  const Eigen::Quaterniond q_new_old(X_new_old.rotation());
  for (size_t i = 0; i < log->tcp_m.size(); ++i) {
    const Eigen::Vector3d p =
        X_new_old * Eigen::Vector3d(log->tcp_m[i][0], log->tcp_m[i][1], log->tcp_m[i][2]);
    log->tcp_m[i] = {p.x(), p.y(), p.z()};
  }
  for (auto& q : log->quat) {
    const Eigen::Quaterniond r = q_new_old * Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
    q = {r.w(), r.x(), r.y(), r.z()};
  }
}

Eigen::Isometry3d IsometryFromRowMajor(const std::array<double, 16>& m) {
  Eigen::Matrix3d r;
  r << m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10];
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::Quaterniond(r).normalized().toRotationMatrix();
  X.translation() = Eigen::Vector3d(m[3], m[7], m[11]);
  return X;
}

PwmScale DetectPwmScale(const Stream& pwm) {
  double max = 0;
  for (const std::vector<double>& row : pwm.rows) max = std::max(max, row.empty() ? 0 : row[0]);
  if (max <= 1.0) return PwmScale::kFraction;
  if (max <= 100.0) return PwmScale::kPercent;
  return PwmScale::kByte;
}

double PwmPercent(double raw, PwmScale scale) {
  switch (scale) {
    case PwmScale::kFraction:
      return 100.0 * raw;
    case PwmScale::kByte:
      return 100.0 * raw / 255.0;
    case PwmScale::kAuto:
    case PwmScale::kPercent:
      break;
  }
  return raw;
}

}  // namespace ssc
