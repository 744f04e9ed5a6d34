// ssc_twin._core, the software-in-the-loop plant behind ssc_twin.sil's stand-ins.
#include "python/src/binding_common.h"
#include "python/src/binding_topics.h"

namespace ssc {
namespace {

// The plant behind the software-in-the-loop stand-ins (ssc_twin.sil): a scene stepped one physics
// step at a time, its tool site driven to a Cartesian target through the scene's servo (the UR
// servoL look-ahead smoothing, runtime/tool_servo.h), read back as the sensors report it. The
// pressure plugin's host average is set to one sample so each reading is one raw sensor packet
// (the lab's host code averages 7 itself). Positions are the tool site (lip-plane centre) in the
// scene frame, m.
class SilPlant {
 public:
  SilPlant(const std::string& scene, const nb::object& seed, int average_samples) {
    scene_ = scene;
    std::string error;
    model_ = ToolModelVariant(ResolveScenePath(scene),
                              {{"average_samples", std::to_string(average_samples)}}, &error);
    if (!model_) Fail(error);
    data_ = MakeData(model_.get(), &error);
    if (!data_) Fail(error);
    if (std::string e = rig_.Bind(model_.get(), data_.get()); !e.empty()) Fail(scene + ": " + e);
    if (rig_.torque_adr < 0) Fail(scene + ": no F/T torque sensor");
    ft_reader_.Bind(model_.get(), rig_.force_sensor, rig_.torque_sensor);
    Reset(seed);
  }
  void Reset(const nb::object& seed) {
    rig_.Reset(model_.get(), data_.get(), SeedArg(seed));
    std::string error;
    if (!rig_.servo->Init(model_.get(), data_.get(), rig_.tool_site, &error)) Fail(error);
    ft_reader_.Update(model_.get(), data_.get());
  }
  // The target the servo tracks, tool site in the scene frame, m.
  void SetTarget(std::array<double, 3> xyz) { rig_.servo->SetTarget({xyz[0], xyz[1], xyz[2]}); }
  std::array<double, 3> Target() const { return rig_.servo->target(); }
  // smoothing_s: the look-ahead time constant (0 = none); max_speed_m_s: the command's speed
  // limit (moveL's speed).
  void SetServo(double smoothing_s, double max_speed_m_s) {
    if (!(smoothing_s >= 0) || !(max_speed_m_s > 0)) {
      Fail("servo: smoothing_s must be >= 0 and max_speed_m_s > 0");
    }
    ServoParams s;
    s.smoothing_s = smoothing_s;
    s.max_speed_m_s = max_speed_m_s;
    rig_.servo->set_params(s);
  }
  // Holds the command where the tool is now (servoStop): no motion left to realise.
  void Stop() {
    ToolServo::State s = rig_.servo->state();
    const Vec3 here = rig_.servo->Measured(data_.get());
    s.target = here;
    s.command = here;
    s.velocity = {0, 0, 0};
    rig_.servo->set_state(s);
  }
  // Physics steps until the simulated time reaches t_s (at least none); returns the time.
  double AdvanceTo(double t_s) {
    nb::gil_scoped_release release;
    const double dt = model_->opt.timestep;
    while (data_->time + 0.5 * dt <= t_s) {
      rig_.servo->Track(model_.get(), data_.get());
      mj_step(model_.get(), data_.get());
      ft_reader_.Update(model_.get(), data_.get());
      for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(data_->qpos[k])) Fail("the simulation became unstable");
      }
    }
    return data_->time;
  }
  std::array<double, 3> ToolPosition() const {
    const double* p = data_->site_xpos + 3 * rig_.tool_site;
    return {p[0], p[1], p[2]};
  }
  // The tool site's rotation, row-major (mjData.site_xmat).
  std::array<double, 9> ToolRotation() const {
    std::array<double, 9> r{};
    for (int k = 0; k < 9; ++k) r[k] = data_->site_xmat[9 * rig_.tool_site + k];
    return r;
  }
  // The newest sensor sample: four chamber vacuums, Pa (positive = vacuum).
  std::array<double, 4> Vacuum() const {
    const double* p = data_->sensordata + rig_.pressure_adr;
    return {p[0], p[1], p[2], p[3]};
  }
  // Force (N) and torque about the site (N m) the transducer exerts on the cup, F/T site frame (z
  // down the cup axis: pressing on a surface reads +z): the F/T sensors on a rigid lip, the
  // trial's contact balance on a flex skirt (runtime/tool_force.h).
  std::array<double, 6> ForceTorque() const { return ft_reader_.Wrench(data_.get()); }
  // MuJoCo's F/T sensors as they read, same frame (they miss a flex skirt's load).
  std::array<double, 6> SensorForceTorque() const {
    std::array<double, 6> ft{};
    for (int k = 0; k < 3; ++k) {
      ft[k] = data_->sensordata[rig_.force_adr + k];
      ft[3 + k] = data_->sensordata[rig_.torque_adr + k];
    }
    return ft;
  }
  double Time() const { return data_->time; }
  double Timestep() const { return model_->opt.timestep; }
  // The sensor's sample rate, Hz (its config).
  double SampleRateHz() const {
    return FindChamberPressureDiagnostics(model_.get(), data_.get())
        ->config()
        .sensor.sample_rate_hz;
  }
  std::string scene() const { return scene_; }
  // A static geom's centre x, y and top z in the scene frame, m (cylinders and boxes).
  std::array<double, 3> GeomTop(const std::string& name) const {
    const int g = mj_name2id(model_.get(), mjOBJ_GEOM, name.c_str());
    if (g < 0) Fail(scene_ + ": no geom '" + name + "'");
    const int type = model_->geom_type[g];
    if (type != mjGEOM_CYLINDER && type != mjGEOM_BOX)
      Fail("geom '" + name + "' is not a cylinder or box");
    const double* p = data_->geom_xpos + 3 * g;
    const double half = model_->geom_size[3 * g + (type == mjGEOM_BOX ? 2 : 1)];
    return {p[0], p[1], p[2] + half};
  }
  // Raw model/data addresses for the viewer (mujoco.MjModel/MjData cannot wrap them; the viewer
  // re-loads the scene and copies qpos).
  std::vector<double> Qpos() const {
    return std::vector<double>(data_->qpos, data_->qpos + model_->nq);
  }

 private:
  std::string scene_;
  ModelPtr model_;
  DataPtr data_;
  RigBinding rig_;
  ToolForceReader ft_reader_;
};

}  // namespace

void BindSil(nb::module_& m) {
  nb::class_<SilPlant>(m, "SilPlant",
                       "A scene stepped from Python with its tool driven to Cartesian targets "
                       "(ssc_twin.sil's robot, sensors and pump).")
      .def(nb::init<const std::string&, const nb::object&, int>(), "scene"_a = DefaultScene(),
           "seed"_a = 1, "average_samples"_a = 1)
      .def("reset", &SilPlant::Reset, "seed"_a)
      .def("set_target", &SilPlant::SetTarget, "xyz_m"_a)
      .def("target", &SilPlant::Target)
      .def("set_servo", &SilPlant::SetServo, "smoothing_s"_a, "max_speed_m_s"_a)
      .def("stop", &SilPlant::Stop)
      .def("advance_to", &SilPlant::AdvanceTo, "t_s"_a)
      .def("tool_position", &SilPlant::ToolPosition)
      .def("tool_rotation", &SilPlant::ToolRotation)
      .def("vacuum", &SilPlant::Vacuum)
      .def("force_torque", &SilPlant::ForceTorque)
      .def("sensor_force_torque", &SilPlant::SensorForceTorque)
      .def("qpos", &SilPlant::Qpos)
      .def("geom_top", &SilPlant::GeomTop, "name"_a)
      .def_prop_ro("time", &SilPlant::Time)
      .def_prop_ro("timestep", &SilPlant::Timestep)
      .def_prop_ro("sample_rate_hz", &SilPlant::SampleRateHz)
      .def_prop_ro("scene", &SilPlant::scene);
}

}  // namespace ssc
