#include "viewer/viewer_app.h"

#include <GLFW/glfw3.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include "common/exit_codes.h"
#include "common/output_file.h"
#include "runtime/mujoco_model.h"
#include "viewer/overlay.h"

namespace ssc {
namespace {

// Everything one viewer session owns; GLFW callbacks reach it through the window user pointer.
struct Session {
  const mjModel* m = nullptr;
  mjData* d = nullptr;
  ContourTrial* trial = nullptr;
  const ChamberPressureDiagnostics* sensor = nullptr;  // looked up once, for the status text
  int tool_site = -1;
  mjvCamera cam;
  mjvOption opt;
  mjvScene scn;
  mjrContext con;
  PressureFigures figures;
  bool paused = false, help = false, tracking = true, step_once = false;
  double speed = 1.0;
  bool button_left = false, button_right = false;
  double last_x = 0, last_y = 0;
  double next_figure_s = 0;  // the figures sample the overlay values every kFigurePeriodS
  int arm_base_body = -1;    // the arm's base (arm scenes): framed together with the cup
  bool close_up = false;     // T: the cup alone, close
  // A test object: the overview frames the cup and the object's edge (its box, world m).
  bool frame_object = false;
  double object_box[4] = {0, 0, 0, 0};  // x_min, y_min, x_max, y_max
};

constexpr double kFigurePeriodS = 0.02;

// The text and figure font for a frame height: the status block and the plots keep their share
// of the frame at any size (at 540 px the 150 % font ran the text into the plots).
int FontScaleFor(int height_px) {
  if (height_px <= 600) return mjFONTSCALE_100;
  if (height_px <= 1100) return mjFONTSCALE_150;
  return mjFONTSCALE_200;
}

// The camera follows the lip (the tool site). With an arm, the overview keeps the whole arm in
// frame: it looks at the middle of base and cup from far enough to see both.
void FollowCup(Session* s) {
  if (!s->tracking) return;
  const mjtNum* cup = s->d->site_xpos + 3 * s->tool_site;
  if (s->close_up || (s->arm_base_body < 0 && !s->frame_object)) {
    for (int k = 0; k < 3; ++k) s->cam.lookat[k] = cup[k];
    s->cam.distance = 0.25;
    return;
  }
  if (s->frame_object) {
    // The box round the object's edge and the cup, seen whole with a margin.
    const double* b = s->object_box;
    const double x0 = std::min(b[0], cup[0]), x1 = std::max(b[2], cup[0]);
    const double y0 = std::min(b[1], cup[1]), y1 = std::max(b[3], cup[1]);
    s->cam.lookat[0] = 0.5 * (x0 + x1);
    s->cam.lookat[1] = 0.5 * (y0 + y1);
    s->cam.lookat[2] = cup[2];
    s->cam.distance = 1.3 * std::hypot(x1 - x0, y1 - y0) + 0.08;
    return;
  }
  const mjtNum* base = s->d->xpos + 3 * s->arm_base_body;
  const mjtNum top[3] = {base[0], base[1], base[2] + 1.0};  // the elbow rises about 1 m
  mjtNum span = 0;
  for (int k = 0; k < 3; ++k) {
    s->cam.lookat[k] = 0.5 * (cup[k] + top[k]) - (k == 2 ? 0.25 : 0.0);
    span = std::max(span, std::fabs(cup[k] - top[k]));
  }
  s->cam.distance = 1.6 * span + 0.4;
}

void Restart(Session* s) {
  s->trial->Reset();
  s->figures.Reset();
  s->next_figure_s = 0;
}

void OnKey(GLFWwindow* w, int key, int, int action, int) {
  if (action == GLFW_RELEASE) return;
  auto* s = static_cast<Session*>(glfwGetWindowUserPointer(w));
  ContourLawParams& law = s->trial->mutable_config().law;
  switch (key) {
    case GLFW_KEY_ESCAPE:
      glfwSetWindowShouldClose(w, 1);
      break;
    case GLFW_KEY_SPACE:
      s->paused = !s->paused;
      break;
    case GLFW_KEY_RIGHT:
      s->step_once = true;
      break;
    case GLFW_KEY_MINUS:
      s->speed = std::max(1.0 / 64, s->speed / 2);
      break;
    case GLFW_KEY_EQUAL:
      s->speed = std::min(64.0, s->speed * 2);
      break;
    case GLFW_KEY_BACKSPACE:
    case GLFW_KEY_R:
      Restart(s);
      break;
    case GLFW_KEY_P:
      law.p_ref_pa = std::min(law.p_grasp_pa * 0.9, law.p_ref_pa * 1.25);
      break;
    case GLFW_KEY_O:
      law.p_ref_pa = std::max(law.p_noise_pa * 1.1, law.p_ref_pa / 1.25);
      break;
    case GLFW_KEY_B:
      law.beta = std::min(100.0, law.beta + 0.5);
      break;
    case GLFW_KEY_V:
      law.beta = std::max(0.0, law.beta - 0.5);
      break;
    case GLFW_KEY_L:
      law.step_mm = std::min(100.0, law.step_mm + 0.5);
      break;
    case GLFW_KEY_K:
      law.step_mm = std::max(0.5, law.step_mm - 0.5);
      break;
    case GLFW_KEY_T:  // arm overview -> cup close-up -> free camera -> overview
      if (s->tracking && !s->close_up && s->arm_base_body >= 0) {
        s->close_up = true;
      } else if (s->tracking) {
        s->tracking = false;
      } else {
        s->tracking = true;
        s->close_up = false;
      }
      break;
    case GLFW_KEY_F1:
      s->help = !s->help;
      break;
    default:
      break;
  }
}

void OnButton(GLFWwindow* w, int, int, int) {
  auto* s = static_cast<Session*>(glfwGetWindowUserPointer(w));
  s->button_left = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  s->button_right = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  glfwGetCursorPos(w, &s->last_x, &s->last_y);
}

void OnMove(GLFWwindow* w, double x, double y) {
  auto* s = static_cast<Session*>(glfwGetWindowUserPointer(w));
  const double dx = x - s->last_x, dy = y - s->last_y;
  s->last_x = x;
  s->last_y = y;
  if (!s->button_left && !s->button_right) return;
  int width = 1, height = 1;
  glfwGetWindowSize(w, &width, &height);
  const bool shift = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS;
  int action = mjMOUSE_ZOOM;
  if (s->button_right) {
    action = shift ? mjMOUSE_MOVE_H : mjMOUSE_MOVE_V;
  } else {
    action = shift ? mjMOUSE_ROTATE_H : mjMOUSE_ROTATE_V;
  }
  mjv_moveCamera(s->m, action, dx / height, dy / height, &s->cam);
}

void OnScroll(GLFWwindow* w, double, double yoffset) {
  auto* s = static_cast<Session*>(glfwGetWindowUserPointer(w));
  mjv_moveCamera(s->m, mjMOUSE_ZOOM, 0, -0.05 * yoffset, &s->cam);
}

void Render(Session* s, mjrRect viewport, double rtf) {
  FollowCup(s);
  mjv_updateScene(s->m, s->d, &s->opt, nullptr, &s->cam, mjCAT_ALL, &s->scn);
  AddTrialDecorations(s->m, s->d, *s->trial, s->tool_site, &s->scn);
  mjr_render(viewport, &s->scn, &s->con);
  // Figures on the right (the pressure one tall enough for its eight-line legend), text at the
  // top left.
  const int fw = viewport.width * 3 / 8, fh = viewport.height * 5 / 9;
  const int ch = viewport.height - fh;
  mjrRect top = {viewport.left + viewport.width - fw, viewport.bottom + viewport.height - fh, fw,
                 fh};
  mjrRect below = {top.left, viewport.bottom, fw, std::min(ch, viewport.height / 3)};
  mjr_figure(top, &s->figures.pressures(), &s->con);
  mjr_figure(below, &s->figures.correction(), &s->con);
  const OverlayValues values = CurrentOverlayValues(*s->trial, s->d);
  const std::string status =
      TrialStatusText(*s->trial, values, rtf, s->paused, s->speed, s->sensor);
  mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport, status.c_str(), nullptr, &s->con);
  if (s->help) {
    mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMLEFT, viewport, ViewerHelpText().c_str(), nullptr,
                &s->con);
  }
}

// Steps the trial once; the figures sample what the overlay shows, in every phase.
void StepOnce(Session* s) {
  s->trial->Step();
  if (s->d->time >= s->next_figure_s) {
    s->figures.Add(CurrentOverlayValues(*s->trial, s->d), s->trial->config().law);
    s->next_figure_s = s->d->time + kFigurePeriodS;
  }
}

bool WritePng(const std::string& path, int width, int height, const std::vector<unsigned char>& rgb,
              std::string* error) {
  // OpenGL rows run bottom-up; PNG rows top-down.
  std::vector<unsigned char> flipped(rgb.size());
  const size_t row = static_cast<size_t>(width) * 3;
  for (int y = 0; y < height; ++y) {
    std::copy(rgb.begin() + static_cast<long>(row * (height - 1 - y)),
              rgb.begin() + static_cast<long>(row * (height - y)),
              flipped.begin() + static_cast<long>(row * y));
  }
  // Encoded in memory, then written whole (a full disk leaves no 0-byte PNG behind).
  std::string png;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<size_t>(size));
  };
  if (stbi_write_png_to_func(append, &png, width, height, 3, flipped.data(),
                             static_cast<int>(row)) == 0) {
    *error = path + ": cannot encode the PNG";
    return false;
  }
  return WriteWholeFile(path, png, error);
}

void ListScenes() {
  std::printf("scenes (ssc view NAME):");
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(SourceDir() + "/scenes", ec)) {
    if (e.path().extension() == ".xml") std::printf(" %s", e.path().stem().c_str());
  }
  std::printf(
      "\ntest objects by name: disk_d02..disk_d14, disk_r35, hole_d02..hole_d14, "
      "corner_aNNN, volute, semicircle_strip, semisquare_strip, fillet\n");
}

// Camera, options, scene and rendering context for the trial, the camera as --camera asks.
// 0, or the exit code when this OpenGL cannot render the off-screen image asked for (the scene
// and the context then freed).
int StartSession(const ViewerOptions& options, mjModel* model, mjData* data, ContourTrial* trial,
                 bool offscreen, Session* s) {
  s->m = model;
  s->d = data;
  s->trial = trial;
  s->sensor = FindChamberPressureDiagnostics(s->m, s->d);
  s->tool_site = s->sensor->site_id();
  mjv_defaultCamera(&s->cam);
  mjv_defaultOption(&s->opt);
  s->opt.geomgroup[4] = 1;  // the lip segments
  mjv_defaultScene(&s->scn);
  mjr_defaultContext(&s->con);
  mjv_makeScene(s->m, &s->scn, 6000);
  if (offscreen) {
    // The off-screen buffer the model asks for may be smaller than the requested image.
    model->vis.global.offwidth = std::max(model->vis.global.offwidth, options.width);
    model->vis.global.offheight = std::max(model->vis.global.offheight, options.height);
  }
  mjr_makeContext(s->m, &s->con, FontScaleFor(options.height));
  if (offscreen && (s->con.offWidth < options.width || s->con.offHeight < options.height)) {
    std::fprintf(stderr,
                 "ssc view: --width %d --height %d: this OpenGL renders off-screen images up to "
                 "%dx%d; ask for at most that\n",
                 options.width, options.height, s->con.offWidth, s->con.offHeight);
    mjr_freeContext(&s->con);
    mjv_freeScene(&s->scn);
    return 2;
  }
  s->cam.type = mjCAMERA_FREE;
  // Arm scenes: the base of the first joint's chain; gantry and probe scenes have none.
  if (mj_name2id(s->m, mjOBJ_JOINT, "gantry_x") < 0 && s->m->njnt > 0 &&
      s->m->jnt_type[0] == mjJNT_HINGE) {
    s->arm_base_body = s->m->jnt_bodyid[0];
  }
  mj_forward(s->m, s->d);
  s->cam.azimuth = 225;
  s->cam.elevation = -25;
  // --camera: the start of T's cycle.
  if (options.camera == ViewerCamera::kCup) {
    s->close_up = true;
  } else if (options.camera == ViewerCamera::kFree) {
    s->tracking = false;
    mjv_defaultFreeCamera(s->m, &s->cam);
  }
  if (options.frame_object && trial->config().target.edge) {
    const std::vector<Point2> outline = trial->config().target.edge->Vertices(1e-3);
    s->frame_object = !outline.empty();
    for (size_t i = 0; i < outline.size(); ++i) {
      const Point2& p = outline[i];
      s->object_box[0] = i ? std::min(s->object_box[0], p[0]) : p[0];
      s->object_box[1] = i ? std::min(s->object_box[1], p[1]) : p[1];
      s->object_box[2] = i ? std::max(s->object_box[2], p[0]) : p[0];
      s->object_box[3] = i ? std::max(s->object_box[3], p[1]) : p[1];
    }
  }
  FollowCup(s);
  s->speed = options.speed;
  return 0;
}

// --screenshot: the steps of a headless trial up to the requested time, then one off-screen
// frame written as a PNG. The exit code.
int TakeScreenshot(const ViewerOptions& options, Session* s) {
  while (s->d->time < options.time_s && s->trial->phase() != TrialPhase::kDone) StepOnce(s);
  mjr_setBuffer(mjFB_OFFSCREEN, &s->con);
  const int w = std::min(options.width, s->con.offWidth);
  const int h = std::min(options.height, s->con.offHeight);
  const mjrRect viewport = {0, 0, w, h};
  Render(s, viewport, -1);  // no real-time factor: nothing ran in real time
  std::vector<unsigned char> rgb(static_cast<size_t>(w) * h * 3);
  mjr_readPixels(rgb.data(), nullptr, viewport, &s->con);
  std::string write_error;
  if (!WritePng(options.screenshot, w, h, rgb, &write_error)) {
    std::fprintf(stderr, "ssc view: %s\n", write_error.c_str());
    return 1;
  }
  const mjtNum* p = s->d->site_xpos + 3 * s->tool_site;
  std::printf("wrote %s (%dx%d) at t = %.4f s; phase %s; tool at %.9f %.9f %.9f m\n",
              options.screenshot.c_str(), w, h, s->d->time, PhaseName(s->trial->phase()), p[0],
              p[1], p[2]);
  std::printf("%s\n", OverlayValuesLine(CurrentOverlayValues(*s->trial, s->d)).c_str());
  return 0;
}

// The window: the trial in real time (times the speed), paused or stepped by the keys, until
// the window is closed.
void RunWindow(GLFWwindow* window, Session* s) {
  ListScenes();
  std::printf("F1 in the window lists the keys.\n");
  glfwSetWindowUserPointer(window, s);
  glfwSetKeyCallback(window, OnKey);
  glfwSetMouseButtonCallback(window, OnButton);
  glfwSetCursorPosCallback(window, OnMove);
  glfwSetScrollCallback(window, OnScroll);
  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  double rtf = 0;
  while (!glfwWindowShouldClose(window)) {
    const auto now = Clock::now();
    const double wall_dt = std::min(0.1, std::chrono::duration<double>(now - last).count());
    last = now;
    const double sim_start = s->d->time;
    if (!s->paused) {
      const double target = s->d->time + wall_dt * s->speed;
      const auto budget_end = now + std::chrono::milliseconds(30);  // keep the UI responsive
      while (s->d->time < target && s->trial->phase() != TrialPhase::kDone &&
             Clock::now() < budget_end) {
        StepOnce(s);
      }
    } else if (s->step_once) {
      StepOnce(s);
    }
    s->step_once = false;
    if (wall_dt > 0) rtf = 0.9 * rtf + 0.1 * (s->d->time - sim_start) / wall_dt;
    mjrRect viewport = {0, 0, 0, 0};
    glfwGetFramebufferSize(window, &viewport.width, &viewport.height);
    Render(s, viewport, rtf);
    glfwSwapBuffers(window);
    glfwPollEvents();
  }
}

}  // namespace

int RunViewer(const ViewerOptions& options) {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || display[0] == '\0') {
    std::fprintf(stderr,
                 "ssc view: no display (DISPLAY is not set); for a screenshot on a "
                 "headless machine run: xvfb-run -a ssc view --screenshot FILE.png\n");
    return kExitFailed;
  }
  if (!glfwInit()) {
    std::fprintf(stderr, "ssc view: cannot open the display '%s' (GLFW init failed)\n", display);
    return kExitFailed;
  }
  std::string error;
  ModelPtr model = LoadModel(options.scene_path, &error);
  if (!model) {
    std::fprintf(stderr, "ssc view: %s\n", error.c_str());
    glfwTerminate();
    return InputErrorCode(error);
  }
  DataPtr data = MakeData(model.get(), &error);
  auto trial = ContourTrial::Create(model.get(), data.get(), options.config, false, &error);
  if (!trial) {
    std::fprintf(stderr, "ssc view: %s\n", error.c_str());
    glfwTerminate();
    return 1;
  }
  if (options.create_outputs) {
    if (const int rc = options.create_outputs(); rc != 0) {
      glfwTerminate();
      return rc;
    }
  }
  const bool offscreen = !options.screenshot.empty();
  if (offscreen) glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  GLFWwindow* window = glfwCreateWindow(options.width, options.height,
                                        "Smart Suction Cup twin (ssc view)", nullptr, nullptr);
  if (window == nullptr) {
    std::fprintf(stderr, "ssc view: cannot create an OpenGL window on '%s'\n", display);
    glfwTerminate();
    return kExitFailed;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  auto session = std::make_unique<Session>();
  Session* s = session.get();
  int code = StartSession(options, model.get(), data.get(), trial.get(), offscreen, s);
  if (code != 0) {
    glfwDestroyWindow(window);
    glfwTerminate();
    return code;
  }
  if (offscreen) {
    code = TakeScreenshot(options, s);
  } else {
    RunWindow(window, s);
  }
  mjv_freeScene(&s->scn);
  mjr_freeContext(&s->con);
  glfwDestroyWindow(window);
  glfwTerminate();
  return code;
}

}  // namespace ssc
