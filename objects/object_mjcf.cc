#include "objects/object_mjcf.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace ssc {
namespace {

namespace fs = std::filesystem;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

std::string Fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.7g", v);
  return buf;
}

std::string Vec(std::initializer_list<double> v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : " ") + Fmt(x);
  return s;
}

bool Save(XMLDocument& doc, const fs::path& path, std::string* error) {
  if (doc.SaveFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    *error = path.string() + ": cannot write";
    return false;
  }
  return true;
}

void AddObjectGeoms(XMLDocument& doc, XMLElement* root, const ObjectSpec& spec) {
  XMLElement* asset = root->InsertNewChildElement("asset");
  XMLElement* mat = asset->InsertNewChildElement("material");
  mat->SetAttribute("name", (spec.name + "_material").c_str());
  mat->SetAttribute("rgba", "0.25 0.45 0.8 1");
  XMLElement* world = root->InsertNewChildElement("worldbody");
  auto object_geom = [&](const std::string& name) {
    XMLElement* g = world->InsertNewChildElement("geom");
    g->SetAttribute("name", name.c_str());
    g->SetAttribute("group", 2);
    g->SetAttribute("contype", 1);
    g->SetAttribute("conaffinity", 1);
    g->SetAttribute("material", (spec.name + "_material").c_str());
    return g;
  };
  // A convex piece as a mesh given by its vertices (MuJoCo takes their convex hull, which is the
  // piece itself, for both collisions and rays), vertices relative to their centroid.
  auto add_mesh = [&](const std::string& name, const std::vector<std::array<double, 3>>& points) {
    double c[3] = {0, 0, 0};
    for (const auto& p : points)
      for (int k = 0; k < 3; ++k) c[k] += p[k] / static_cast<double>(points.size());
    std::ostringstream v;
    for (const auto& p : points) {
      v << Fmt(p[0] - c[0]) << ' ' << Fmt(p[1] - c[1]) << ' ' << Fmt(p[2] - c[2]) << ' ';
    }
    XMLElement* mesh = asset->InsertNewChildElement("mesh");
    mesh->SetAttribute("name", name.c_str());
    mesh->SetAttribute("vertex", v.str().c_str());
    XMLElement* g = object_geom(name);
    g->SetAttribute("type", "mesh");
    g->SetAttribute("mesh", name.c_str());
    g->SetAttribute("pos", Vec({c[0], c[1], c[2]}).c_str());
  };
  int index = 0;
  for (const ConvexPiece& piece : spec.pieces) {
    const std::string name = spec.name + "_" + std::to_string(index++);
    const double half_h = 0.5 * (piece.top_z - piece.bottom_z), mid_z = 0.5 * (piece.top_z + piece.bottom_z);
    if (piece.cylinder) {
      XMLElement* g = object_geom(name);
      g->SetAttribute("type", "cylinder");
      g->SetAttribute("size", Vec({piece.radius_m, half_h}).c_str());
      g->SetAttribute("pos", Vec({piece.centre[0], piece.centre[1], mid_z}).c_str());
      continue;
    }
    if (!piece.hull_points.empty()) {  // free convex hull (fillet slices)
      add_mesh(name, piece.hull_points);
      continue;
    }
    std::vector<std::array<double, 3>> prism;  // the polygon at the bottom and at the top
    for (double z : {piece.bottom_z, piece.top_z}) {
      for (const Point2& p : piece.polygon) prism.push_back({p[0], p[1], z});
    }
    add_mesh(name, prism);
  }
  for (const HeightField& h : spec.heightfields) {
    const std::string name = spec.name + "_hfield" + std::to_string(index++);
    const double lo = *std::min_element(h.z_m.begin(), h.z_m.end());
    const double hi = *std::max_element(h.z_m.begin(), h.z_m.end());
    // MuJoCo's elevation rows run from +y to -y; ours run from -y: write them flipped.
    std::ostringstream e;
    for (int row = h.nrow - 1; row >= 0; --row) {
      for (int col = 0; col < h.ncol; ++col) {
        const double z = h.z_m[static_cast<size_t>(row) * h.ncol + col];
        e << Fmt((z - lo) / std::max(1e-12, hi - lo)) << ' ';
      }
    }
    XMLElement* hf = asset->InsertNewChildElement("hfield");
    hf->SetAttribute("name", name.c_str());
    hf->SetAttribute("nrow", h.nrow);
    hf->SetAttribute("ncol", h.ncol);
    hf->SetAttribute("size", Vec({h.half_x_m, h.half_y_m, hi - lo, 0.005}).c_str());
    hf->SetAttribute("elevation", e.str().c_str());
    XMLElement* g = object_geom(name);
    g->SetAttribute("type", "hfield");
    g->SetAttribute("hfield", name.c_str());
    g->SetAttribute("pos", Vec({h.centre[0], h.centre[1], lo}).c_str());
  }
  (void)doc;
}

// Loads a repository scene as the template for an object scene.
bool SceneFromTemplate(const fs::path& template_path, const fs::path& object_file,
                       const fs::path& out_path, const std::string& model_name,
                       std::string* error) {
  XMLDocument doc;
  if (doc.LoadFile(template_path.c_str()) != tinyxml2::XML_SUCCESS) {
    *error = template_path.string() + ": cannot read the template scene";
    return false;
  }
  XMLElement* root = doc.FirstChildElement("mujoco");
  if (!root) {
    *error = template_path.string() + ": no <mujoco> root";
    return false;
  }
  root->SetAttribute("model", model_name.c_str());
  const fs::path dir = template_path.parent_path();
  // Absolute model paths; drop the disk; lower the table.
  std::vector<XMLElement*> stack = {root};
  std::vector<XMLElement*> remove;
  while (!stack.empty()) {
    XMLElement* e = stack.back();
    stack.pop_back();
    const char* file = e->Attribute("file");
    if (file && (std::string(e->Name()) == "include" || std::string(e->Name()) == "model")) {
      e->SetAttribute("file", fs::absolute(dir / file).lexically_normal().c_str());
    }
    const char* name = e->Attribute("name");
    if (name && std::string(e->Name()) == "geom" && std::string(name) == "disk") remove.push_back(e);
    if (name && std::string(e->Name()) == "geom" && std::string(name) == "table") {
      e->SetAttribute("pos", Vec({0, 0, kTableZ}).c_str());
    }
    for (XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) stack.push_back(c);
  }
  for (XMLElement* e : remove) e->Parent()->DeleteChild(e);
  XMLElement* include = doc.NewElement("include");
  include->SetAttribute("file", object_file.filename().c_str());
  root->InsertFirstChild(include);
  return Save(doc, out_path, error);
}

}  // namespace

bool WriteObjectScenes(const ObjectSpec& spec, const std::string& out_dir,
                       const std::string& repo_dir, std::string* error) {
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) {
    *error = out_dir + ": " + ec.message();
    return false;
  }
  const fs::path object_file = fs::path(out_dir) / (spec.name + "_object.xml");
  {
    XMLDocument doc;
    XMLElement* root = doc.NewElement("mujoco");
    root->SetAttribute("model", (spec.name + "_object").c_str());
    doc.InsertFirstChild(root);
    root->InsertNewChildElement("compiler")->SetAttribute("angle", "radian");
    doc.InsertFirstChild(doc.NewComment((" " + spec.description +
                                         ". Generated by ssc objects; top face at z = 10 mm. ")
                                            .c_str()));
    AddObjectGeoms(doc, root, spec);
    if (!Save(doc, object_file, error)) return false;
  }
  const fs::path scenes = fs::path(repo_dir) / "scenes";
  return SceneFromTemplate(scenes / "disk_benchmark.xml", object_file,
                           fs::path(out_dir) / (spec.name + ".xml"), spec.name, error) &&
         SceneFromTemplate(scenes / "disk_benchmark_gantry.xml", object_file,
                           fs::path(out_dir) / (spec.name + "_gantry.xml"),
                           spec.name + "_gantry", error);
}

int WriteAllObjectScenes(const std::string& out_dir, const std::string& repo_dir,
                         std::string* error) {
  int count = 0;
  for (const ObjectSpec& spec : AllObjects()) {
    if (!WriteObjectScenes(spec, out_dir, repo_dir, error)) return -1;
    ++count;
  }
  return count;
}

}  // namespace ssc
