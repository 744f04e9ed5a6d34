// ssc_defaults_doc: prints docs/defaults.md from the code's tables (studies/defaults_doc.h).
#include <cstdio>

#include "studies/defaults_doc.h"

int main() {
  std::fputs(ssc::DefaultsMarkdown().c_str(), stdout);
  return 0;
}
