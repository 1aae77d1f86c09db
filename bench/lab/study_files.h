#pragma once
// The files a study writes (bench/lab/): its output folder, whole text files, and the quoting of
// CSV fields and JSON strings, one definition for every study.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include "core/error.h"

namespace rayo {

// Creates `dir` and its parents; InputError(dir, ...) with the system's reason when it cannot.
inline void create_output_dir(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(dir, "cannot create the output directory: " + ec.message());
}

// Writes `text` to `path`, replacing it; InputError(path, "cannot write") on failure.
inline void write_text_file(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw InputError(path, "cannot write");
}

// `s` as a JSON string: quotes and backslashes escaped, control characters dropped.
inline std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) >= 0x20) out += c;
    }
    return out + "\"";
}

// `s` as a CSV field: quoted when it holds a comma or a quote.
inline std::string csv_field(const std::string& s) {
    return s.find_first_of(",\"") == std::string::npos ? s : "\"" + s + "\"";
}

// `table` (its first row the heading) as aligned text columns, or as a Markdown table: the first
// column left-aligned, the others right-aligned.
inline void write_aligned_table(std::ostream& out,
                                const std::vector<std::vector<std::string>>& table, bool markdown) {
    std::vector<size_t> widths;
    for (const auto& cells : table) {
        widths.resize(std::max(widths.size(), cells.size()), 0);
        for (size_t c = 0; c < cells.size(); ++c) widths[c] = std::max(widths[c], cells[c].size());
    }
    for (size_t row = 0; row < table.size(); ++row) {
        const auto& cells = table[row];
        for (size_t c = 0; c < cells.size(); ++c) {
            if (markdown) out << "| ";
            out << (c == 0 ? std::left : std::right) << std::setw(int(widths[c])) << cells[c]
                << (markdown ? " " : "  ");
        }
        out << (markdown ? "|\n" : "\n");
        if (markdown && row == 0) {
            for (size_t c = 0; c < cells.size(); ++c) {
                out << "|" << (c == 0 ? ":" : "") << std::string(widths[c] + 1, '-')
                    << (c == 0 ? "" : ":");
            }
            out << "|\n";
        }
    }
    out << std::left;
}

}  // namespace rayo
