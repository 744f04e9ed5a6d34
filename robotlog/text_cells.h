// Text helpers shared by the CSV readers (internal to robotlog/): strict, locale-independent
// number parsing, line and cell splitting, and cell text safe to put in an error message.
#ifndef SSC_ROBOTLOG_TEXT_CELLS_H_
#define SSC_ROBOTLOG_TEXT_CELLS_H_

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "robotlog/log_types.h"

namespace ssc::text {

// Outcome of parsing one cell as a number.
enum class NumberParse { kOk, kEmpty, kNotANumber, kNonFinite };

// Whole-cell parse (surrounding blanks allowed, nothing else): "1e5" ok, "1e5x" not a number,
// "nan", "inf" and overflow non-finite.
NumberParse ParseDouble(std::string_view cell, double* value);
// Whole-cell integer parse (optional sign); false on anything else, including overflow.
bool ParseInt64(std::string_view cell, long long* value);

std::string_view Trim(std::string_view s);
std::string Lower(std::string_view s);

// Splits on commas; "a,,b" has an empty middle cell and "a," an empty last one.
std::vector<std::string_view> SplitCells(std::string_view line);

// Calls `fn(line_number, line)` for each line of `text` (1-based numbers, '\r\n' and '\n'
// endings, a leading UTF-8 byte-order mark dropped); stops early when `fn` returns false.
template <typename Fn>
void ForEachLine(std::string_view text, Fn fn) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  int line_no = 0;
  while (!text.empty()) {
    const size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line_no < 0x7fffffff) ++line_no;
    if (!fn(line_no, line)) return;
    if (end == std::string_view::npos) return;
    text.remove_prefix(end + 1);
  }
}

// Longest line any reader accepts. A lab log row is under 300 bytes and a header under 1 kB;
// the bound keeps a file without line breaks (or a binary file) from being read whole.
inline constexpr size_t kMaxLineBytes = 64 * 1024;

// Reads `path` line by line (at most kMaxLineBytes per line, never the whole file at once) and
// calls `fn(line_number, line)` as ForEachLine does. False with an error naming the file and
// line when the file cannot be read or a line is too long; `stopped` tells that fn said stop.
// With `torn_last` given, a last line without a line end after at least one whole line is not
// delivered: *torn_last gets its line number (0 when there is none). A logger stopped while
// writing leaves such a row, whose last cell may be cut mid-number.
bool ForEachFileLine(const std::string& path, const std::function<bool(int, std::string_view)>& fn,
                     LoadError* error, bool* stopped = nullptr, int* torn_last = nullptr);

// The cell as it may appear in a message: quoted, at most 24 characters, unprintable bytes as
// \xNN (fuzzed or binary input must not garble the error text).
std::string Quote(std::string_view cell);

// Checks that `path` is a readable regular file (common/input_file.h): reports a missing file,
// a directory, a FIFO or device (which would block or never end) and an unreadable file apart.
bool CheckReadableFile(const std::string& path, LoadError* error);

// Python's repr() of a float, as the lab's logger writes values: the shortest round-trip digits,
// always with a '.' or an exponent ("100.0", "1e-05", "101339.671875").
std::string PyFloat(double v);

// Fills an error.
void SetError(LoadError* error, const std::string& file, int line, int column,
              const std::string& message);

// Shortest text that reads back as the same double (std::to_chars).
std::string FormatDouble(double v);

// Saturating size_t -> int for line and column numbers.
int ToInt(size_t n);

}  // namespace ssc::text

#endif  // SSC_ROBOTLOG_TEXT_CELLS_H_
