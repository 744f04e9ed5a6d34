// An MJCF file's text for the checks that read a scene before MuJoCo does (config values,
// included files): its <!-- comments --> blanked out, so a commented-out line is not taken for
// a live one, with the newlines kept so line numbers in messages stay right. Header-only.
#ifndef SSC_COMMON_XML_TEXT_H_
#define SSC_COMMON_XML_TEXT_H_

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ssc {

// False (and *text empty) when the file cannot be opened: the callers leave that to MuJoCo's
// own message.
inline bool ReadXmlWithoutComments(const std::filesystem::path& file, std::string* text) {
  text->clear();
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::stringstream buf;
  buf << in.rdbuf();
  *text = buf.str();
  std::string& t = *text;
  for (size_t a = t.find("<!--"); a != std::string::npos; a = t.find("<!--", a)) {
    const size_t b = t.find("-->", a);
    const size_t end = b == std::string::npos ? t.size() : b + 3;
    for (size_t i = a; i < end; ++i) {
      if (t[i] != '\n') t[i] = ' ';
    }
    a = end;
  }
  return true;
}

}  // namespace ssc

#endif  // SSC_COMMON_XML_TEXT_H_
