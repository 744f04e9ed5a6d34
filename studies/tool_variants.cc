#include "studies/tool_variants.h"

#include <tinyxml2.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace ssc {
namespace {

constexpr const char* kPressurePlugin = "ssc.chamber_pressure";

bool ReadText(const std::string& path, std::string* text) {
  std::ifstream in(path);
  std::stringstream buf;
  buf << in.rdbuf();
  *text = buf.str();
  return static_cast<bool>(in);
}

// The <instance> of the pressure plugin under <extension><plugin plugin="ssc.chamber_pressure">.
tinyxml2::XMLElement* PressureInstance(tinyxml2::XMLDocument* doc) {
  tinyxml2::XMLElement* root = doc->RootElement();
  if (root == nullptr) return nullptr;
  for (auto* ext = root->FirstChildElement("extension"); ext;
       ext = ext->NextSiblingElement("extension")) {
    for (auto* p = ext->FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin")) {
      const char* name = p->Attribute("plugin");
      if (name && std::strcmp(name, kPressurePlugin) == 0) return p->FirstChildElement("instance");
    }
  }
  return nullptr;
}

bool HoldsPressureInstance(const std::string& xml) {
  tinyxml2::XMLDocument doc;
  return doc.Parse(xml.c_str()) == tinyxml2::XML_SUCCESS && PressureInstance(&doc) != nullptr;
}

// Collects the files `xml` (at `dir`) includes or attaches, depth first, under the names used.
bool CollectFiles(const std::string& xml, const std::filesystem::path& dir, int depth,
                  ModelTexts* texts, std::string* error) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str()) != tinyxml2::XML_SUCCESS) {
    *error = (dir / "?").string() + ": not XML: " + doc.ErrorStr();
    return false;
  }
  std::vector<tinyxml2::XMLElement*> stack = {doc.RootElement()};
  while (!stack.empty()) {
    tinyxml2::XMLElement* e = stack.back();
    stack.pop_back();
    for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) stack.push_back(c);
    const char* file = e->Attribute("file");
    if (!file || (std::strcmp(e->Name(), "include") != 0 && std::strcmp(e->Name(), "model") != 0)) {
      continue;
    }
    const std::filesystem::path path = (dir / file).lexically_normal();
    std::string text;
    if (depth > 8 || !ReadText(path.string(), &text)) {
      *error = path.string() + ": cannot read (referred to as '" + file + "')";
      return false;
    }
    texts->files.emplace_back(file, text);
    if (!CollectFiles(text, path.parent_path(), depth + 1, texts, error)) return false;
  }
  return true;
}

}  // namespace

std::string ToolXmlWithConfig(const std::string& tool_xml, const PluginConfig& config,
                              std::string* error) {
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLElement* instance =
      doc.Parse(tool_xml.c_str()) == tinyxml2::XML_SUCCESS ? PressureInstance(&doc) : nullptr;
  if (instance == nullptr) {
    *error =
        std::string("no <plugin plugin=\"") + kPressurePlugin + "\"><instance> in the tool model";
    return "";
  }
  for (const auto& [key, value] : config) {
    if (value.empty()) {  // MuJoCo would pass it as if the key were absent
      *error = "config key '" + key + "' has an empty value";
      return "";
    }
    tinyxml2::XMLElement* entry = nullptr;
    for (auto* c = instance->FirstChildElement("config"); c && !entry;
         c = c->NextSiblingElement("config")) {
      if (c->Attribute("key") && key == c->Attribute("key")) entry = c;
    }
    if (entry == nullptr) {
      entry = instance->InsertNewChildElement("config");
      entry->SetAttribute("key", key.c_str());
    }
    entry->SetAttribute("value", value.c_str());
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

std::unique_ptr<ToolModelVariants> ToolModelVariants::Read(const std::string& scene_path,
                                                           std::string* error) {
  std::unique_ptr<ToolModelVariants> v(new ToolModelVariants());
  v->label_ = scene_path;
  if (std::string e = CheckScenePath(scene_path); !e.empty()) {
    *error = e;
    return nullptr;
  }
  if (!ReadText(scene_path, &v->texts_.main_xml)) {
    *error = scene_path + ": cannot read";
    return nullptr;
  }
  if (!CollectFiles(v->texts_.main_xml, std::filesystem::path(scene_path).parent_path(), 0,
                    &v->texts_, error)) {
    return nullptr;
  }
  if (!HoldsPressureInstance(v->texts_.main_xml)) {
    for (size_t i = 0; i < v->texts_.files.size() && v->tool_file_ < 0; ++i) {
      if (HoldsPressureInstance(v->texts_.files[i].second)) v->tool_file_ = static_cast<int>(i);
    }
    if (v->tool_file_ < 0) {
      *error = scene_path + ": no file of the scene holds the " + kPressurePlugin + " instance";
      return nullptr;
    }
  }
  return v;
}

std::string ToolModelVariants::ToolXml(const ToolVariant& variant, std::string* error) const {
  const std::string& base = tool_file_ < 0 ? texts_.main_xml : texts_.files[tool_file_].second;
  std::string xml = ToolXmlWithConfig(base, variant.config, error);
  if (!xml.empty() && variant.lip_segments > 0) {
    xml = ToolWithLipSegments(xml, variant.lip_segments, error);
  }
  if (xml.empty()) {
    const std::string file = tool_file_ < 0 ? label_ : texts_.files[tool_file_].first;
    *error = file + ": " + *error;
  }
  return xml;
}

ModelPtr ToolModelVariants::Compile(const ToolVariant& variant, std::string* error) const {
  const std::string tool = ToolXml(variant, error);
  if (tool.empty()) return nullptr;
  ModelTexts texts = texts_;
  // Every name the tool file is referred to by gets the variant (a scene may name it twice).
  const std::string& base = tool_file_ < 0 ? texts_.main_xml : texts_.files[tool_file_].second;
  if (tool_file_ < 0) texts.main_xml = tool;
  for (auto& [name, text] : texts.files) {
    if (text == base) text = tool;
  }
  return LoadModelFromTexts(texts, label_ + " (tool variant)", error);
}

ModelPtr ToolModelVariant(const std::string& scene_path, const PluginConfig& config,
                          std::string* error) {
  const auto variants = ToolModelVariants::Read(scene_path, error);
  return variants ? variants->Compile({config, 0}, error) : nullptr;
}

std::string ToolWithLipSegments(const std::string& tool_xml, int segments, std::string* error) {
  using tinyxml2::XMLElement;
  if (segments < 4 || segments > 256 || segments % 4 != 0) {
    *error = "lip segments = " + std::to_string(segments) + ": need a multiple of 4 in [4, 256]";
    return "";
  }
  tinyxml2::XMLDocument doc;
  if (doc.Parse(tool_xml.c_str()) != tinyxml2::XML_SUCCESS) {
    *error = "the tool model does not parse as XML";
    return "";
  }
  // Find the body that carries the lip segments: bodies named <stem><n>, the stem ending in
  // "lip_" (the tool model's own "lip_0" ...; "ssc_lip_0" in a file that holds the tool with the
  // scene's prefix already applied).
  auto segment_stem = [](const XMLElement* e) -> std::string {
    const char* name = e->Attribute("name");
    if (std::strcmp(e->Name(), "body") != 0 || name == nullptr) return "";
    const std::string n = name;
    const std::size_t digits = n.find_last_not_of("0123456789") + 1;
    if (digits == n.size() || digits < 4 || n.compare(digits - 4, 4, "lip_") != 0) return "";
    return n.substr(0, digits);
  };
  XMLElement* cup = nullptr;
  std::vector<XMLElement*> stack = {doc.RootElement()};
  while (!stack.empty() && cup == nullptr) {
    XMLElement* e = stack.back();
    stack.pop_back();
    for (XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
      if (!segment_stem(c).empty()) cup = e;
      stack.push_back(c);
    }
  }
  if (cup == nullptr) {
    *error = "the tool model has no lip segment bodies (lip_*)";
    return "";
  }
  double radius = 0, z = 0, total_stiffness = 0;
  int old = 0;
  std::vector<XMLElement*> lips;
  std::string stem, joint_class, geom_class;  // as the old segments name and class them
  for (XMLElement* b = cup->FirstChildElement("body"); b; b = b->NextSiblingElement("body")) {
    if (segment_stem(b).empty()) continue;
    if (stem.empty()) {
      stem = segment_stem(b);
      const XMLElement* j = b->FirstChildElement("joint");
      const XMLElement* g = b->FirstChildElement("geom");
      if (j && j->Attribute("class")) joint_class = j->Attribute("class");
      if (g && g->Attribute("class")) geom_class = g->Attribute("class");
    }
    double x = 0, y = 0, zz = 0;
    std::sscanf(b->Attribute("pos"), "%lf %lf %lf", &x, &y, &zz);
    radius += std::hypot(x, y);
    z = zz;
    ++old;
    lips.push_back(b);
  }
  if (joint_class.empty() || geom_class.empty()) {
    *error = "the tool model's lip segment " + stem +
             "0 has no joint and geom with a default class (the class holds their stiffness)";
    return "";
  }
  radius /= old;
  // The per-segment stiffness lives in the segments' joint default class; keep the total.
  for (XMLElement* d = doc.RootElement()->FirstChildElement("default"); d;
       d = d->NextSiblingElement("default")) {
    for (XMLElement* c = d->FirstChildElement("default"); c; c = c->NextSiblingElement("default")) {
      if (c->Attribute("class") && joint_class == c->Attribute("class")) {
        if (XMLElement* j = c->FirstChildElement("joint")) {
          total_stiffness = j->DoubleAttribute("stiffness") * old;
          j->SetAttribute("stiffness", total_stiffness / segments);
        }
      }
    }
  }
  for (XMLElement* b : lips) cup->DeleteChild(b);
  const double half = std::max(0.0002, M_PI * radius / segments - 0.00003);
  for (int i = 0; i < segments; ++i) {
    const double a = 2 * M_PI * (i + 0.5) / segments;
    char buf[160];
    XMLElement* body = cup->InsertNewChildElement("body");
    body->SetAttribute("name", (stem + std::to_string(i)).c_str());
    std::snprintf(buf, sizeof(buf), "%.6f %.6f %.6f", radius * std::cos(a), radius * std::sin(a),
                  z);
    body->SetAttribute("pos", buf);
    XMLElement* joint = body->InsertNewChildElement("joint");
    joint->SetAttribute("name", (stem + std::to_string(i)).c_str());
    joint->SetAttribute("class", joint_class.c_str());
    XMLElement* geom = body->InsertNewChildElement("geom");
    geom->SetAttribute("name", (stem + std::to_string(i)).c_str());
    geom->SetAttribute("class", geom_class.c_str());
    const double tx = -std::sin(a), ty = std::cos(a);
    std::snprintf(buf, sizeof(buf), "%.6f %.6f 0 %.6f %.6f 0", -half * tx, -half * ty, half * tx,
                  half * ty);
    geom->SetAttribute("fromto", buf);
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

}  // namespace ssc
