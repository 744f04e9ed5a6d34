#include "geometry/contour_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Closest points closer than this to a piece's end count as the junction.
constexpr double kJunctionM = 1e-9;

double Dist2(const Point2& p, double x, double y) {
  return (p[0] - x) * (p[0] - x) + (p[1] - y) * (p[1] - y);
}

Point2 LeftOf(const Point2& t) { return {-t[1], t[0]}; }

// Polar pieces are parametrised by t in [0, |sweep|], theta = theta0 + sign(sweep) t.
double Sign(double v) { return v < 0 ? -1.0 : 1.0; }

double RadiusAt(const PathPiece& p, double t) { return p.r0_m + p.dr_drad * Sign(p.sweep_rad) * t; }

// Antiderivative of sqrt(r^2 + k^2) in r: the spiral's arc length is a difference of it over k.
double SpiralG(double r, double k) {
  return 0.5 * (r * std::sqrt(r * r + k * k) + k * k * std::asinh(r / std::fabs(k)));
}

// Arc length of a polar piece from t = 0 to t.
double PolarLength(const PathPiece& p, double t) {
  if (p.dr_drad == 0) return p.r0_m * t;
  const double k = p.dr_drad, signed_k = k * Sign(p.sweep_rad);
  return (SpiralG(RadiusAt(p, t), k) - SpiralG(p.r0_m, k)) / signed_k;
}

// Inverse of PolarLength (Newton; the length grows strictly with t).
double PolarParameter(const PathPiece& p, double u) {
  const double t_max = std::fabs(p.sweep_rad);
  if (p.dr_drad == 0) return std::clamp(u / p.r0_m, 0.0, t_max);
  const double k2 = p.dr_drad * p.dr_drad;
  double t = u / std::sqrt(p.r0_m * p.r0_m + k2);
  for (int i = 0; i < 50; ++i) {
    const double r = RadiusAt(p, t);
    const double step = (PolarLength(p, t) - u) / std::sqrt(r * r + k2);
    t = std::clamp(t - step, 0.0, t_max);
    if (std::fabs(step) < 1e-14) break;
  }
  return t;
}

Point2 PolarPoint(const PathPiece& p, double t) {
  const double th = p.theta0_rad + Sign(p.sweep_rad) * t, r = RadiusAt(p, t);
  return {p.centre[0] + r * std::cos(th), p.centre[1] + r * std::sin(th)};
}

// Closest point of piece p to (x, y) among arc lengths [u_lo, u_hi] along it: its arc length
// and squared distance.
void ClosestOnPiece(const PathPiece& p, double x, double y, double u_lo, double u_hi, double* u,
                    double* d2) {
  if (!p.polar) {
    const double len = p.Length();
    const double dx = p.b[0] - p.a[0], dy = p.b[1] - p.a[1];
    double v = len > 0 ? ((x - p.a[0]) * dx + (y - p.a[1]) * dy) / len : 0.0;
    v = std::clamp(v, u_lo, u_hi);
    *u = v;
    *d2 = Dist2(p.PointAt(v), x, y);
    return;
  }
  // Polar: sample every half degree, then a golden-section search around the best sample (the
  // squared distance is unimodal over one sample spacing on both sides).
  const double t_lo = PolarParameter(p, u_lo), t_hi = PolarParameter(p, u_hi);
  const int n = std::clamp(static_cast<int>(std::ceil((t_hi - t_lo) / (0.5 * kPi / 180))), 2, 4000);
  int best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) {
    const double d = Dist2(PolarPoint(p, t_lo + (t_hi - t_lo) * i / n), x, y);
    if (d < best_d2) {
      best_d2 = d;
      best = i;
    }
  }
  double a = t_lo + (t_hi - t_lo) * std::max(0, best - 1) / n;
  double b = t_lo + (t_hi - t_lo) * std::min(n, best + 1) / n;
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double c = b - g * (b - a), e = a + g * (b - a);
  double fc = Dist2(PolarPoint(p, c), x, y), fe = Dist2(PolarPoint(p, e), x, y);
  for (int i = 0; i < 60 && b - a > 1e-13; ++i) {
    if (fc < fe) {
      b = e;
      e = c;
      fe = fc;
      c = b - g * (b - a);
      fc = Dist2(PolarPoint(p, c), x, y);
    } else {
      a = c;
      c = e;
      fc = fe;
      e = a + g * (b - a);
      fe = Dist2(PolarPoint(p, e), x, y);
    }
  }
  const double t = 0.5 * (a + b);
  const double dt = Dist2(PolarPoint(p, t), x, y);
  if (dt <= best_d2) {
    *u = std::clamp(PolarLength(p, t), u_lo, u_hi);
    *d2 = dt;
  } else {
    *u = std::clamp(PolarLength(p, t_lo + (t_hi - t_lo) * best / n), u_lo, u_hi);
    *d2 = best_d2;
  }
}

}  // namespace

PathPiece PathPiece::Segment(const Point2& from, const Point2& to) {
  PathPiece p;
  p.a = from;
  p.b = to;
  return p;
}

PathPiece PathPiece::Arc(const Point2& centre, double radius_m, double theta0_rad,
                         double sweep_rad) {
  return Spiral(centre, radius_m, 0.0, theta0_rad, sweep_rad);
}

PathPiece PathPiece::Spiral(const Point2& centre, double r0_m, double dr_drad, double theta0_rad,
                            double sweep_rad) {
  PathPiece p;
  p.polar = true;
  p.centre = centre;
  p.r0_m = r0_m;
  p.dr_drad = dr_drad;
  p.theta0_rad = theta0_rad;
  p.sweep_rad = sweep_rad;
  p.a = PolarPoint(p, 0);
  p.b = PolarPoint(p, std::fabs(sweep_rad));
  return p;
}

double PathPiece::Length() const {
  if (!polar) return std::hypot(b[0] - a[0], b[1] - a[1]);
  return PolarLength(*this, std::fabs(sweep_rad));
}

Point2 PathPiece::PointAt(double u) const {
  if (!polar) {
    const double len = Length();
    const double v = len > 0 ? std::clamp(u / len, 0.0, 1.0) : 0.0;
    return {a[0] + v * (b[0] - a[0]), a[1] + v * (b[1] - a[1])};
  }
  return PolarPoint(*this, PolarParameter(*this, u));
}

Point2 PathPiece::TangentAt(double u) const {
  if (!polar) {
    const double len = Length();
    return len > 0 ? Point2{(b[0] - a[0]) / len, (b[1] - a[1]) / len} : Point2{1, 0};
  }
  const double t = PolarParameter(*this, u), s = Sign(sweep_rad);
  const double th = theta0_rad + s * t, r = RadiusAt(*this, t);
  // d(point)/d(theta), times the walking sense.
  const double dx = s * (dr_drad * std::cos(th) - r * std::sin(th));
  const double dy = s * (dr_drad * std::sin(th) + r * std::cos(th));
  const double n = std::hypot(dx, dy);
  return {dx / n, dy / n};
}

ContourPath::ContourPath(std::vector<PathPiece> pieces, bool closed)
    : pieces_(std::move(pieces)), closed_(closed) {
  for (const PathPiece& p : pieces_) {
    start_m_.push_back(total_m_);
    total_m_ += p.Length();
  }
}

void ContourPath::Locate(double s, int* piece, double* u) const {
  if (closed_ && total_m_ > 0) s = std::fmod(std::fmod(s, total_m_) + total_m_, total_m_);
  s = std::clamp(s, 0.0, total_m_);
  const auto it = std::upper_bound(start_m_.begin(), start_m_.end(), s);
  const int i = std::max(0, static_cast<int>(it - start_m_.begin()) - 1);
  *piece = i;
  *u = std::min(s - start_m_[i], pieces_[i].Length());
}

Point2 ContourPath::PointAt(double s) const {
  int i;
  double u;
  Locate(s, &i, &u);
  return pieces_[i].PointAt(u);
}

Point2 ContourPath::TangentAt(double s) const {
  int i;
  double u;
  Locate(s, &i, &u);
  return pieces_[i].TangentAt(u);
}

Point2 ContourPath::LeftNormalAt(double s) const { return LeftOf(TangentAt(s)); }

ContourProjection ContourPath::Project(double x, double y) const {
  return ProjectWithin(x, y, 0.0, total_m_);
}

ContourProjection ContourPath::ProjectWithin(double x, double y, double s_min, double s_max) const {
  ContourProjection best;
  double best_d2 = std::numeric_limits<double>::infinity();
  // Closed contours: the window may wrap past the start; try it shifted by one turn each way.
  const int turns = closed_ ? 1 : 0;
  for (int k = -turns; k <= turns; ++k) {
    const double lo = s_min + k * total_m_, hi = s_max + k * total_m_;
    for (size_t i = 0; i < pieces_.size(); ++i) {
      const double len = pieces_[i].Length();
      const double u_lo = std::max(0.0, lo - start_m_[i]), u_hi = std::min(len, hi - start_m_[i]);
      if (u_lo > u_hi) continue;
      double u, d2;
      ClosestOnPiece(pieces_[i], x, y, u_lo, u_hi, &u, &d2);
      if (d2 < best_d2) {
        best_d2 = d2;
        best.arc_m = start_m_[i] + u;
        best.point = pieces_[i].PointAt(u);
      }
    }
  }
  best.distance_m = std::sqrt(best_d2);
  return best;
}

double ContourPath::SignedDistance(double x, double y) const {
  const ContourProjection pr = Project(x, y);
  if (pr.distance_m == 0) return 0;
  int i;
  double u;
  Locate(pr.arc_m, &i, &u);
  const int n = static_cast<int>(pieces_.size());
  const double len = pieces_[i].Length();
  Point2 normal = LeftOf(pieces_[i].TangentAt(u));
  // At a junction, the sum of both pieces' left normals decides the side.
  if (u <= kJunctionM && (closed_ || i > 0)) {
    const PathPiece& prev = pieces_[(i + n - 1) % n];
    const Point2 np = LeftOf(prev.TangentAt(prev.Length()));
    normal = {normal[0] + np[0], normal[1] + np[1]};
  } else if (u >= len - kJunctionM && (closed_ || i + 1 < n)) {
    const PathPiece& next = pieces_[(i + 1) % n];
    const Point2 nn = LeftOf(next.TangentAt(0));
    normal = {normal[0] + nn[0], normal[1] + nn[1]};
  }
  const double side = (x - pr.point[0]) * normal[0] + (y - pr.point[1]) * normal[1];
  return side > 0 ? -pr.distance_m : pr.distance_m;
}

ContourPath ContourPath::Polygon(const std::vector<Point2>& points, bool closed) {
  std::vector<PathPiece> pieces;
  std::vector<Point2> q;
  for (const Point2& p : points) {
    if (q.empty() || p != q.back()) q.push_back(p);
  }
  if (closed && q.size() > 1 && q.front() == q.back()) q.pop_back();
  for (size_t i = 0; i + 1 < q.size(); ++i) pieces.push_back(PathPiece::Segment(q[i], q[i + 1]));
  if (closed && q.size() > 2) pieces.push_back(PathPiece::Segment(q.back(), q.front()));
  if (pieces.empty() && !q.empty()) pieces.push_back(PathPiece::Segment(q[0], q[0]));
  return ContourPath(std::move(pieces), closed);
}

ContourPath ContourPath::Circle(const Point2& centre, double radius_m) {
  return ContourPath({PathPiece::Arc(centre, radius_m, 0, 2 * kPi)}, true);
}

std::vector<Point2> ContourPath::Vertices(double tolerance_m) const {
  std::vector<Point2> line;
  for (const PathPiece& p : pieces_) {
    line.push_back(p.a);
    if (!p.polar) continue;
    const double r_max = std::max(p.r0_m, RadiusAt(p, std::fabs(p.sweep_rad)));
    const double step = 2 * std::acos(std::max(-1.0, 1 - tolerance_m / r_max));
    const int chords = std::max(1, static_cast<int>(std::ceil(std::fabs(p.sweep_rad) / step)));
    for (int k = 1; k < chords; ++k) {
      line.push_back(PolarPoint(p, std::fabs(p.sweep_rad) * k / chords));
    }
  }
  if (!closed_ && !pieces_.empty()) line.push_back(pieces_.back().b);
  return line;
}

}  // namespace ssc
