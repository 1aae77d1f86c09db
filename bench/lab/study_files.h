#pragma once
// The files a study writes (bench/lab/): its output folder, whole text files, and the quoting of
// CSV fields and JSON strings, one definition for every study.
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

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

}  // namespace rayo
