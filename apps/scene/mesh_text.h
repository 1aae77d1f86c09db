#pragma once
// Reading the text mesh formats (ASCII PLY, ASCII STL, OFF: apps/scene/ply_reader.h,
// stl_reader.h, off_reader.h) line by line and word by word, numbers parsed whole with
// std::from_chars (no locale, no partial read: "1-5" and "1FF" are not numbers), and words quoted
// safely in messages (a malformed file may hold any byte).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace rayo {

// The lines of a text, numbered from `first_number`: '\n' ends a line (a '\r' before it is a
// blank, see split_words). No copy: the lines are views into `text`.
class TextLines {
  public:
    explicit TextLines(std::string_view text, size_t first_number = 1)
        : m_text(text), m_number(first_number - 1) {}
    // The next line (without its '\n') into `line`; false at the end of the text.
    bool next(std::string_view& line);
    // The number of the line `next` returned last (first_number - 1 before the first).
    size_t number() const { return m_number; }
    // The offset in the text just past the line `next` returned last (and its '\n').
    size_t offset() const { return m_at; }

  private:
    std::string_view m_text;
    size_t m_at = 0;
    size_t m_number;
};

// Whether `c` separates words: space, tab, CR, vertical tab, form feed.
inline bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Splits `line` at blanks into `words` (cleared first).
void split_words(std::string_view line, std::vector<std::string_view>& words);

// `word` as one number, all of it: a decimal or scientific float ("-2", "1e-3", ".5", "+1", also
// "nan" and "inf", which callers refuse where they must be finite). False for anything else,
// a number out of double's range included.
bool parse_number(std::string_view word, double& out);

// `word` as one decimal integer, all of it ("-5", "+3", "42"); false for anything else.
bool parse_integer(std::string_view word, long long& out);

// `word` for a message: in single quotes, bytes outside printable ASCII as \xNN, and cut at 48
// characters ("...") so that a megabyte of junk does not become the message.
std::string quote_word(std::string_view word);

}  // namespace rayo
