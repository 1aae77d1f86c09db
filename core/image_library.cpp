#include "core/image_library.h"

#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace rayo {

namespace {

struct LoadState {
    std::once_flag once;
    const ImageLibrary* library = nullptr;
    std::string error;
    std::atomic<bool> loaded{false};
};

LoadState& load_state() {
    static LoadState state;
    return state;
}

// The directory of the running executable ("" when /proc is not mounted).
std::string executable_directory() {
    std::string path(4096, '\0');
    const ssize_t n = ::readlink("/proc/self/exe", path.data(), path.size());
    if (n <= 0 || static_cast<size_t>(n) >= path.size()) return "";
    path.resize(static_cast<size_t>(n));
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? "" : path.substr(0, slash);
}

// The directory of the shared object this code is linked into, when it is not the executable
// (the Python module, build/python/rayo*.so); "" otherwise.
std::string library_directory() {
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&executable_directory), &info) == 0 ||
        info.dli_fname == nullptr) {
        return "";
    }
    const std::string path = info.dli_fname;
    const size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return "";
    const std::string dir = path.substr(0, slash);
    return dir == executable_directory() ? "" : dir;
}

// Where the module is looked for, in order: $RAYO_IMAGE_MODULE alone when set; else beside the
// executable (the build tree), then in ../lib/rayo from it (an install moved to another prefix);
// for a library loaded by another program (the Python module), its folder's parent (the build
// tree) and PREFIX/lib/rayo from PREFIX/lib/pythonX.Y/dist-packages (an install); then the install
// directory configured at build time.
std::vector<std::string> module_candidates() {
    const char* env = std::getenv("RAYO_IMAGE_MODULE");
    if (env != nullptr && env[0] != '\0') return {env};
    std::vector<std::string> paths;
    const std::string dir = executable_directory();
    if (!dir.empty()) {
        paths.push_back(dir + "/" + kImageModuleName);
        paths.push_back(dir + "/../lib/rayo/" + kImageModuleName);
    }
    if (const std::string library = library_directory(); !library.empty()) {
        paths.push_back(library + "/../" + kImageModuleName);  // build/python/..
        paths.push_back(library + "/../../rayo/" +
                        kImageModuleName);  // lib/pythonX.Y/dist-packages
    }
    paths.push_back(std::string(RAYO_IMAGE_MODULE_INSTALL_DIR) + "/" + kImageModuleName);
    return paths;
}

std::string load_failure(const std::string& tried) {
    return "cannot load the image I/O module " + std::string(kImageModuleName) +
           " (OpenImageIO), which reading and writing images needs: " + tried +
           " (it is built beside the rayo executable and installed in " +
           RAYO_IMAGE_MODULE_INSTALL_DIR + "; RAYO_IMAGE_MODULE names another path)";
}

// Loads the module (once, under load_state().once). The handle is never closed: writers and
// texture caches made by the module may live until exit.
void load_module(LoadState& state) {
    std::string tried;
    for (const std::string& path : module_candidates()) {
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        std::string reason;
        if (handle == nullptr) {
            const char* message = ::dlerror();
            reason = message != nullptr ? message : "unknown dlopen error";
        } else {
            const auto entry =
                reinterpret_cast<ImageLibraryEntry>(::dlsym(handle, kImageLibraryEntry));
            const ImageLibrary* library = entry != nullptr ? entry(kImageLibraryAbi) : nullptr;
            if (library != nullptr) {
                state.library = library;
                state.loaded.store(true, std::memory_order_release);
                return;
            }
            reason = path + ": " +
                     (entry == nullptr
                          ? std::string("no ") + kImageLibraryEntry + " (not rayo's image module)"
                          : "built for another version of rayo (interface " +
                                std::to_string(kImageLibraryAbi) + " expected)");
            ::dlclose(handle);
        }
        if (!tried.empty()) tried += "; ";
        tried += reason;
    }
    state.error = load_failure(tried);
}

// The preloading thread, joined at exit so that the process does not end while the dynamic
// loader runs the libraries' initialisers on it.
struct Preloader {
    std::thread thread;
    ~Preloader() {
        if (thread.joinable()) thread.join();
    }
};

}  // namespace

const ImageLibrary& image_library() {
    LoadState& state = load_state();
    std::call_once(state.once, [&] { load_module(state); });
    if (state.library == nullptr) throw std::runtime_error(state.error);
    return *state.library;
}

void preload_image_library() {
    LoadState& state = load_state();  // constructed first: destroyed after the preloader
    static std::mutex mutex;
    static Preloader preloader;
    std::lock_guard<std::mutex> lock(mutex);
    if (preloader.thread.joinable() || state.loaded.load(std::memory_order_acquire)) return;
    preloader.thread =
        std::thread([&state] { std::call_once(state.once, [&] { load_module(state); }); });
}

void check_image_library() {
    if (image_library_loaded()) return;
    std::string tried;
    for (const std::string& path : module_candidates()) {
        // A bare name is for dlopen's search path: only loading it tells.
        if (path.find('/') == std::string::npos || ::access(path.c_str(), R_OK) == 0) return;
        const int error = errno;
        if (!tried.empty()) tried += "; ";
        tried += path + ": " + std::strerror(error);
    }
    throw std::runtime_error(load_failure(tried));
}

bool image_library_loaded() {
    return load_state().loaded.load(std::memory_order_acquire);
}

}  // namespace rayo
