#include "apps/scene/mesh_text.h"

#include <charconv>
#include <cstdio>
#include <system_error>

namespace rayo {

bool TextLines::next(std::string_view& line) {
    if (m_at >= m_text.size()) return false;
    const size_t end = m_text.find('\n', m_at);
    const size_t stop = end == std::string_view::npos ? m_text.size() : end;
    line = m_text.substr(m_at, stop - m_at);
    m_at = end == std::string_view::npos ? m_text.size() : end + 1;
    ++m_number;
    return true;
}

void split_words(std::string_view line, std::vector<std::string_view>& words) {
    words.clear();
    size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && is_blank(line[at])) ++at;
        const size_t start = at;
        while (at < line.size() && !is_blank(line[at])) ++at;
        if (at > start) words.push_back(line.substr(start, at - start));
    }
}

namespace {

// from_chars takes no '+': one before a digit or a '.' is dropped ("+1", "+.5").
std::string_view without_plus(std::string_view word) {
    if (word.size() > 1 && word[0] == '+' && word[1] != '-' && word[1] != '+') {
        word.remove_prefix(1);
    }
    return word;
}

}  // namespace

bool parse_number(std::string_view word, double& out) {
    word = without_plus(word);
    if (word.empty()) return false;
    const char* end = word.data() + word.size();
    const std::from_chars_result r = std::from_chars(word.data(), end, out);
    return r.ec == std::errc() && r.ptr == end;
}

bool parse_integer(std::string_view word, long long& out) {
    word = without_plus(word);
    if (word.empty()) return false;
    const char* end = word.data() + word.size();
    const std::from_chars_result r = std::from_chars(word.data(), end, out);
    return r.ec == std::errc() && r.ptr == end;
}

std::string quote_word(std::string_view word) {
    constexpr size_t kShown = 48;
    std::string out = "'";
    for (size_t i = 0; i < word.size() && i < kShown; ++i) {
        const auto c = static_cast<unsigned char>(word[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        }
    }
    if (word.size() > kShown) out += "...";
    return out + "'";
}

}  // namespace rayo
