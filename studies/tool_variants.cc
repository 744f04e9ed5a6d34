#include "studies/tool_variants.h"

#include <tinyxml2.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace ssc {

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
  // Find the body that carries the lip segments (bodies named ssc_lip_<n>).
  auto is_segment = [](const XMLElement* e) {
    const char* name = e->Attribute("name");
    return std::strcmp(e->Name(), "body") == 0 && name && std::strncmp(name, "ssc_lip_", 8) == 0 &&
           std::isdigit(static_cast<unsigned char>(name[8]));
  };
  XMLElement* cup = nullptr;
  std::vector<XMLElement*> stack = {doc.RootElement()};
  while (!stack.empty() && cup == nullptr) {
    XMLElement* e = stack.back();
    stack.pop_back();
    for (XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
      if (is_segment(c)) cup = e;
      stack.push_back(c);
    }
  }
  if (cup == nullptr) {
    *error = "the tool model has no lip segment bodies (ssc_lip_*)";
    return "";
  }
  double radius = 0, z = 0, total_stiffness = 0;
  int old = 0;
  std::vector<XMLElement*> lips;
  for (XMLElement* b = cup->FirstChildElement("body"); b; b = b->NextSiblingElement("body")) {
    if (!is_segment(b)) continue;
    double x = 0, y = 0, zz = 0;
    std::sscanf(b->Attribute("pos"), "%lf %lf %lf", &x, &y, &zz);
    radius += std::hypot(x, y);
    z = zz;
    ++old;
    lips.push_back(b);
  }
  if (old == 0) {
    *error = "the tool model has no lip segment bodies (ssc_lip_*)";
    return "";
  }
  radius /= old;
  // The per-segment stiffness lives in the ssc_lip default class; keep the total.
  for (XMLElement* d = doc.RootElement()->FirstChildElement("default"); d;
       d = d->NextSiblingElement("default")) {
    for (XMLElement* c = d->FirstChildElement("default"); c; c = c->NextSiblingElement("default")) {
      if (c->Attribute("class") && std::strcmp(c->Attribute("class"), "ssc_lip") == 0) {
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
    body->SetAttribute("name", ("ssc_lip_" + std::to_string(i)).c_str());
    std::snprintf(buf, sizeof(buf), "%.6f %.6f %.6f", radius * std::cos(a), radius * std::sin(a), z);
    body->SetAttribute("pos", buf);
    XMLElement* joint = body->InsertNewChildElement("joint");
    joint->SetAttribute("name", ("ssc_lip_" + std::to_string(i)).c_str());
    joint->SetAttribute("class", "ssc_lip");
    XMLElement* geom = body->InsertNewChildElement("geom");
    geom->SetAttribute("name", ("ssc_lip_" + std::to_string(i)).c_str());
    geom->SetAttribute("class", "ssc_lip");
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
