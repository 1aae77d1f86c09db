#include "core/path_util.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace rayo {

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::string parent_directory(const std::string& path) {
    // POSIX dirname: drop trailing slashes, then the last component, then the slashes before it.
    size_t end = path.find_last_not_of('/');
    if (end == std::string::npos) return path.empty() ? "." : "/";  // "" or only slashes
    const size_t slash = path.find_last_of('/', end);
    if (slash == std::string::npos) return ".";
    end = path.find_last_not_of('/', slash);
    return end == std::string::npos ? "/" : path.substr(0, end + 1);
}

std::string join_path(const std::string& dir, const std::string& name) {
    if ((!name.empty() && name.front() == '/') || dir.empty() || dir == ".") return name;
    return dir.back() == '/' ? dir + name : dir + "/" + name;
}

}  // namespace rayo
