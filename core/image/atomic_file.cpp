#include "core/image/atomic_file.h"

#include <unistd.h>

#include <cstring>

#include "core/path_util.h"

namespace rayo {

size_t max_name_length(const std::string& dir) {
    const long limit = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    return limit > 0 ? static_cast<size_t>(limit) : 255;
}

std::string temporary_path_for(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    const std::string suffix =
        ".tmp" + std::to_string(static_cast<long>(::getpid())) + lower_extension(path);
    const size_t limit = max_name_length(dir.empty() ? "." : dir);
    if (1 + name.size() + suffix.size() > limit) name.resize(limit - 1 - suffix.size());
    return dir + "." + name + suffix;
}

std::string write_failure(std::string message, int error, const std::string& tmp,
                          const std::string& path) {
    for (size_t at = message.find(tmp); at != std::string::npos; at = message.find(tmp, at)) {
        message.replace(at, tmp.size(), path);
        at += path.size();
    }
    if (message.empty()) message = "unknown error";
    if (error != 0 && message.find(std::strerror(error)) == std::string::npos) {
        message += std::string(" (") + std::strerror(error) + ")";
    }
    return message;
}

}  // namespace rayo
