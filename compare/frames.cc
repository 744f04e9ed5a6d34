#include "compare/frames.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace ssc {
namespace {

Eigen::Matrix3d BaseRotation(LogFrame frame) {
  return frame == LogFrame::kBaseLink
             ? Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix()
             : Eigen::Matrix3d::Identity();
}

// Distance from a point (world) to a geom, by its shape; other shapes by their bounding box.
double GeomDistance(const mjModel* m, const mjData* d, int g, const Eigen::Vector3d& p) {
  const Eigen::Map<const Eigen::Vector3d> c(d->geom_xpos + 3 * g);
  const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R(d->geom_xmat + 9 * g);
  const Eigen::Vector3d l = R.transpose() * (p - c);
  const double* size = m->geom_size + 3 * g;
  switch (m->geom_type[g]) {
    case mjGEOM_SPHERE:
      return std::max(0.0, l.norm() - size[0]);
    case mjGEOM_CYLINDER:
      return std::hypot(std::max(0.0, std::hypot(l.x(), l.y()) - size[0]),
                        std::max(0.0, std::fabs(l.z()) - size[1]));
    case mjGEOM_BOX: {
      const Eigen::Vector3d out(std::max(0.0, std::fabs(l.x()) - size[0]),
                                std::max(0.0, std::fabs(l.y()) - size[1]),
                                std::max(0.0, std::fabs(l.z()) - size[2]));
      return out.norm();
    }
    default: {
      const double* box = m->geom_aabb + 6 * g;  // centre, half sizes, geom frame
      const Eigen::Vector3d out(std::max(0.0, std::fabs(l.x() - box[0]) - box[3]),
                                std::max(0.0, std::fabs(l.y() - box[1]) - box[4]),
                                std::max(0.0, std::fabs(l.z() - box[2]) - box[5]));
      return out.norm();
    }
  }
}

struct DataFree {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

}  // namespace

bool ParseLogFrame(const std::string& name, LogFrame* frame) {
  if (name == "base_link") {
    *frame = LogFrame::kBaseLink;
  } else if (name == "base") {
    *frame = LogFrame::kUrBase;
  } else {
    return false;
  }
  return true;
}

const char* LogFrameName(LogFrame frame) {
  return frame == LogFrame::kBaseLink ? "base_link" : "base";
}

std::vector<SceneObject> FindSceneObjects(const mjModel* m) {
  std::vector<SceneObject> objects;
  std::unique_ptr<mjData, DataFree> d(mj_makeData(m));
  mj_kinematics(m, d.get());
  for (int g = 0; g < m->ngeom; ++g) {
    const int body = m->geom_bodyid[g];
    if (m->body_weldid[body] != 0 || m->geom_type[g] == mjGEOM_PLANE ||
        (m->geom_contype[g] == 0 && m->geom_conaffinity[g] == 0)) {
      continue;
    }
    SceneObject o;
    const char* name = mj_id2name(m, mjOBJ_GEOM, g);
    o.name = name ? name : "geom " + std::to_string(g);
    o.geom = g;
    o.x_m = d->geom_xpos[3 * g];
    o.y_m = d->geom_xpos[3 * g + 1];
    // The top: the highest point of the geom's bounding box in the world.
    const double* box = m->geom_aabb + 6 * g;
    double top = -1e9;
    for (int corner = 0; corner < 8; ++corner) {
      Eigen::Vector3d l(box[0] + ((corner & 1) ? box[3] : -box[3]),
                        box[1] + ((corner & 2) ? box[4] : -box[4]),
                        box[2] + ((corner & 4) ? box[5] : -box[5]));
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R(d->geom_xmat + 9 * g);
      top = std::max(top, (R * l).z() + d->geom_xpos[3 * g + 2]);
    }
    o.top_z_m = top;
    if (m->geom_type[g] == mjGEOM_CYLINDER) o.radius_m = m->geom_size[3 * g];
    o.half_size_m = {box[3], box[4]};
    objects.push_back(o);
  }
  return objects;
}

ObjectPose DiskPoseFromLog(const LoadedLog& loaded, double contact_depth_m) {
  ObjectPose o;
  const ProcessedLog& log = loaded.log;
  if (loaded.format == LogFormat::kPlain || log.t_s.empty()) return o;
  // The lowest steady height: the 2nd percentile of the TCP z (noise and a dip stay out).
  std::vector<double> z;
  for (const auto& p : log.tcp_m) z.push_back(p[2]);
  std::nth_element(z.begin(), z.begin() + static_cast<long>(z.size() / 50), z.end());
  const double follow_z = z[z.size() / 50];
  o.known = true;
  o.x_m = log.tcp_m.front()[0];
  o.y_m = log.tcp_m.front()[1];
  o.top_z_m = follow_z + contact_depth_m;
  const LabRunArgs& a = loaded.raw.args;
  if (!std::isnan(a.disk_radius_mm)) o.radius_m = a.disk_radius_mm * 1e-3;
  o.source =
      "the log (disk benchmark: centre = the TCP where the recording starts, top = the "
      "lowest steady TCP height + the twin's lip depth at the approach force)";
  if (!a.history.empty() && !std::isnan(a.start_offset_m)) {
    // The lab's scripts record the history from RTDE, in the UR Base frame (base_link turned
    // 180 deg about z): the distance is measured in the disk's frame, from whichever reading of
    // the history puts its first point by the disk (the centre lies ~0.6 m from either origin).
    const HistoryRow& h = a.history.front();
    const double as_logged = std::hypot(h.x_m - o.x_m, h.y_m - o.y_m);
    const double turned = std::hypot(-h.x_m - o.x_m, -h.y_m - o.y_m);
    char buf[240];
    std::snprintf(buf, sizeof(buf),
                  "first controller iteration %.1f mm from the centre%s (start_offset %.1f mm)",
                  std::min(as_logged, turned) * 1e3,
                  turned < as_logged ? ", its history read in the UR Base frame" : "",
                  a.start_offset_m * 1e3);
    o.note = buf;
  }
  return o;
}

Eigen::Isometry3d SceneFromLog(LogFrame frame, const ObjectPose& object,
                               const SceneObject& scene_object) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  if (!object.known) {
    X.linear() = BaseRotation(frame);
    return X;
  }
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(-object.yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
      BaseRotation(frame);
  X.linear() = R;
  X.translation() = Eigen::Vector3d(scene_object.x_m, scene_object.y_m, scene_object.top_z_m) -
                    R * Eigen::Vector3d(object.x_m, object.y_m, object.top_z_m);
  return X;
}

const SceneObject* NearestSceneObject(const std::vector<SceneObject>& objects, LogFrame frame,
                                      const ObjectPose& object) {
  const Eigen::Vector3d p = BaseRotation(frame) * Eigen::Vector3d(object.x_m, object.y_m, 0);
  const SceneObject* best = nullptr;
  double best_d = 1e18;
  for (const SceneObject& o : objects) {
    const double dist = std::hypot(o.x_m - p.x(), o.y_m - p.y());
    if (dist < best_d) {
      best_d = dist;
      best = &o;
    }
  }
  return best;
}

Reach ClosestApproach(const mjModel* m, const std::vector<SceneObject>& objects,
                      const ProcessedLog& scene_log) {
  Reach r;
  std::unique_ptr<mjData, DataFree> d(mj_makeData(m));
  mj_kinematics(m, d.get());
  for (size_t i = 0; i < scene_log.t_s.size(); ++i) {
    const Eigen::Vector3d p(scene_log.tcp_m[i][0], scene_log.tcp_m[i][1], scene_log.tcp_m[i][2]);
    for (const SceneObject& o : objects) {
      const double dist = GeomDistance(m, d.get(), o.geom, p);
      if (dist < r.closest_m) {
        r.closest_m = dist;
        r.t_s = scene_log.t_s[i];
        r.tcp_m = scene_log.tcp_m[i];
        r.object = o.name;
      }
    }
  }
  return r;
}

}  // namespace ssc
