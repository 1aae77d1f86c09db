#pragma once
// A GoogleTest fixture that runs the built `rayo` executable (RAYO_CLI_PATH) in a fresh folder
// of its own, so tests can check exit status, messages and which files a command left behind.
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace rayo_test {

// Two spheres, one partly off the image, a mirror: reflections, shadows and the background;
// 150 × 100 pixels (the streaming and resume tests).
inline const char* const kSceneNff =
    "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 150 100\n"
    "b 0.2 0.3 0.5\nl 3 3 3\nl -3 2 4\nf 1 0 0 0.8 0.2 20 0 1\ns 0.3 0.2 0 1\n"
    "f 0.9 0.9 0.9 0.2 0.8 50 0.6 1\ns -1.8 -0.6 -1 1.2\n";

struct CommandResult {
    int exit_code;
    std::string output;  // stdout and stderr together
};

// A run watched from outside: its bounds (wall time, peak memory) and how it ended.
struct WatchedResult {
    int exit_code = -1;      // -1 when killed by a signal or by the time limit
    int shell_status = -1;   // as a shell reports it: the exit code, or 128 + the signal
    bool timed_out = false;  // still running after the limit (then killed)
    double seconds = 0.0;    // wall time until it ended
    long peak_rss_kb = 0;    // its own peak resident set (wait4)
    std::string output;      // stdout and stderr together
};

class CliFixture : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = std::filesystem::temp_directory_path() /
                ("rayo_cli_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" +
                 info->name());
        std::filesystem::remove_all(m_dir);
        std::filesystem::create_directories(m_dir);
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }

    // The float RGBA pixels of an image in the folder (empty when it cannot be read): for
    // comparing renders whose files differ in metadata (render times).
    std::vector<float> read_pixels(const std::string& name) const {
        std::vector<float> rgba;
        auto in = OIIO::ImageInput::open((m_dir / name).string());
        if (!in) return rgba;
        rgba.resize(static_cast<size_t>(in->spec().width) * in->spec().height * 4);
        EXPECT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, rgba.data()));
        return rgba;
    }

    // Runs `rayo ARGS` in the folder; the log lives beside it so listings see only rayo's files.
    // `launcher` (e.g. "mpirun -np 3") goes before the executable.
    CommandResult run(const std::string& args, const std::string& launcher = "") const {
        const std::filesystem::path log = log_path();
        const std::string command = "cd '" + m_dir.string() + "' && " + launcher + " '" +
                                    RAYO_CLI_PATH "' " + args + " > '" + log.string() + "' 2>&1";
        const int status = std::system(command.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, take_log(log)};
    }

    // Runs `rayo ARGS` (one argument per element, no shell) in the folder with SIGINT and
    // SIGTERM at their defaults, calls `while_running(pid)` every millisecond until it returns
    // true (e.g. once it has sent a signal) or the process ends, and kills it after
    // `limit_seconds`.
    // `file_size_limit_bytes` > 0 sets RLIMIT_FSIZE for the run (writes beyond it fail).
    WatchedResult run_watched(const std::vector<std::string>& args, double limit_seconds,
                              const std::function<bool(pid_t)>& while_running = {},
                              rlim_t file_size_limit_bytes = 0) const {
        const std::filesystem::path log = log_path();
        std::vector<std::string> argv_text{RAYO_CLI_PATH};
        argv_text.insert(argv_text.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (std::string& a : argv_text) argv.push_back(a.data());
        argv.push_back(nullptr);
        const auto start = std::chrono::steady_clock::now();
        const pid_t pid = ::fork();
        if (pid == 0) {
            std::signal(SIGINT, SIG_DFL);
            std::signal(SIGTERM, SIG_DFL);
            const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (fd < 0 || ::chdir(m_dir.c_str()) != 0) ::_exit(127);
            if (file_size_limit_bytes > 0) {
                const struct rlimit limit { file_size_limit_bytes, file_size_limit_bytes };
                ::setrlimit(RLIMIT_FSIZE, &limit);
            }
            ::dup2(fd, 1);
            ::dup2(fd, 2);
            ::execv(argv[0], argv.data());
            ::_exit(127);
        }
        WatchedResult result;
        bool watching = static_cast<bool>(while_running);
        int status = 0;
        struct rusage usage {};
        for (;;) {
            const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
            if (done == pid) break;
            const double elapsed =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (elapsed > limit_seconds && !result.timed_out) {
                result.timed_out = true;
                ::kill(pid, SIGKILL);
            }
            if (watching && while_running(pid)) watching = false;
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        result.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        result.peak_rss_kb = usage.ru_maxrss;
        result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        result.shell_status = WIFEXITED(status)     ? WEXITSTATUS(status)
                              : WIFSIGNALED(status) ? 128 + WTERMSIG(status)
                                                    : -1;
        result.output = take_log(log);
        return result;
    }

    // The run's log beside the test's folder (so that listings see only rayo's files).
    std::filesystem::path log_path() const {
        return m_dir.parent_path() / (m_dir.filename().string() + ".log");
    }

    // The log's text; the log is removed.
    static std::string take_log(const std::filesystem::path& log) {
        std::ifstream in(log);
        std::stringstream text;
        text << in.rdbuf();
        std::filesystem::remove(log);
        return text.str();
    }

    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const std::filesystem::path p = m_dir / name;
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }

    // The bytes of a file in the folder (empty when it cannot be read).
    std::string read(const std::string& name) const {
        std::ifstream in(m_dir / name, std::ios::binary);
        std::stringstream bytes;
        bytes << in.rdbuf();
        return bytes.str();
    }

    // Every file and folder below the test's folder, relative to it.
    std::set<std::string> listing() const {
        std::set<std::string> names;
        for (const auto& e : std::filesystem::recursive_directory_iterator(m_dir)) {
            names.insert(std::filesystem::relative(e.path(), m_dir).string());
        }
        return names;
    }

    std::filesystem::path m_dir;
};

}  // namespace rayo_test
