// One CSV text cell as every table the project writes spells it, so that any CSV reader
// (RFC 4180: Python's csv, pandas, spreadsheets) gets the text back: quoted, a quote doubled,
// and a line break (CR or LF) turned into a space, since a row never spans lines (a resuming
// reader trusts whole lines only).
#ifndef SSC_COMMON_CSV_CELL_H_
#define SSC_COMMON_CSV_CELL_H_

#include <string>
#include <string_view>

namespace ssc {

inline std::string CsvCell(std::string_view text) {
  std::string out = "\"";
  out.reserve(text.size() + 2);
  for (char c : text) {
    if (c == '"')
      out += "\"\"";
    else if (c == '\n' || c == '\r')
      out += ' ';
    else
      out += c;
  }
  return out + "\"";
}

// The text of a cell as CsvCell writes it (a cell without quotes is returned as it stands).
inline std::string CsvCellText(std::string_view cell) {
  if (cell.size() < 2 || cell.front() != '"' || cell.back() != '"') return std::string(cell);
  std::string out;
  for (size_t i = 1; i + 1 < cell.size(); ++i) {
    out += cell[i];
    if (cell[i] == '"' && i + 2 < cell.size() && cell[i + 1] == '"') ++i;
  }
  return out;
}

}  // namespace ssc

#endif  // SSC_COMMON_CSV_CELL_H_
