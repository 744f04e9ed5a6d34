#include "geometry/contour.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ssc {
namespace {

int SegmentCount(const Polyline& p) {
  const int n = static_cast<int>(p.points.size());
  if (n < 2) return 0;
  return p.closed ? n : n - 1;
}

const Point2& Vertex(const Polyline& p, int i) {
  return p.points[static_cast<size_t>(i) % p.points.size()];
}

// Closest point parameter t in [0, 1] on segment a-b to (x, y), and its squared distance.
void Closest(const Point2& a, const Point2& b, double x, double y, double* t, double* d2) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double len2 = dx * dx + dy * dy;
  double u = len2 > 0 ? ((x - a[0]) * dx + (y - a[1]) * dy) / len2 : 0.0;
  u = std::clamp(u, 0.0, 1.0);
  const double px = a[0] + u * dx - x, py = a[1] + u * dy - y;
  *t = u;
  *d2 = px * px + py * py;
}

}  // namespace

double Polyline::Length() const {
  double s = 0;
  for (int i = 0; i < SegmentCount(*this); ++i) {
    const Point2& a = Vertex(*this, i);
    const Point2& b = Vertex(*this, i + 1);
    s += std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  return s;
}

double Polyline::Distance(double x, double y) const {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < SegmentCount(*this); ++i) {
    double t, d2;
    Closest(Vertex(*this, i), Vertex(*this, i + 1), x, y, &t, &d2);
    best = std::min(best, d2);
  }
  return std::sqrt(best);
}

double Polyline::ArcPosition(double x, double y) const {
  double best = std::numeric_limits<double>::infinity(), best_s = 0, s = 0;
  for (int i = 0; i < SegmentCount(*this); ++i) {
    const Point2& a = Vertex(*this, i);
    const Point2& b = Vertex(*this, i + 1);
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    double t, d2;
    Closest(a, b, x, y, &t, &d2);
    if (d2 < best) {
      best = d2;
      best_s = s + t * len;
    }
    s += len;
  }
  return best_s;
}

double Polyline::ArcPositionIn(double x, double y, double s_min, double s_max) const {
  double best = std::numeric_limits<double>::infinity(), best_s = s_min, s = 0;
  for (int i = 0; i < SegmentCount(*this); ++i) {
    const Point2& a = Vertex(*this, i);
    const Point2& b = Vertex(*this, i + 1);
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (s + len >= s_min && s <= s_max && len > 0) {
      double t, d2;
      Closest(a, b, x, y, &t, &d2);
      // Keep the candidate inside the window.
      const double u = std::clamp(t, (s_min - s) / len, (s_max - s) / len);
      const double u_c = std::clamp(u, 0.0, 1.0);
      const double px = a[0] + u_c * (b[0] - a[0]) - x, py = a[1] + u_c * (b[1] - a[1]) - y;
      const double dd = px * px + py * py;
      if (dd < best) {
        best = dd;
        best_s = s + u_c * len;
      }
    }
    s += len;
  }
  return best_s;
}

Point2 Polyline::PointAt(double s) const {
  const double total = Length();
  if (closed && total > 0) s = std::fmod(std::fmod(s, total) + total, total);
  s = std::clamp(s, 0.0, total);
  for (int i = 0; i < SegmentCount(*this); ++i) {
    const Point2& a = Vertex(*this, i);
    const Point2& b = Vertex(*this, i + 1);
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (s <= len || i == SegmentCount(*this) - 1) {
      const double u = len > 0 ? std::clamp(s / len, 0.0, 1.0) : 0.0;
      return {a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])};
    }
    s -= len;
  }
  return points.empty() ? Point2{0, 0} : points.front();
}

Point2 Polyline::TangentAt(double s) const {
  const double h = 1e-5;
  const Point2 a = PointAt(s - h), b = PointAt(s + h);
  const double n = std::hypot(b[0] - a[0], b[1] - a[1]);
  return n > 0 ? Point2{(b[0] - a[0]) / n, (b[1] - a[1]) / n} : Point2{1, 0};
}

}  // namespace ssc
