#pragma once
// A GoogleTest fixture that runs the built `rayo` executable (RAYO_CLI_PATH) in a fresh folder
// of its own, so tests can check exit status, messages and which files a command left behind.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace rayo_test {

struct CommandResult {
    int exit_code;
    std::string output;  // stdout and stderr together
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

    // Runs `rayo ARGS` in the folder; the log lives beside it so listings see only rayo's files.
    CommandResult run(const std::string& args) const {
        const std::filesystem::path log =
            m_dir.parent_path() / (m_dir.filename().string() + ".log");
        const std::string command = "cd '" + m_dir.string() + "' && '" RAYO_CLI_PATH "' " + args +
                                    " > '" + log.string() + "' 2>&1";
        const int status = std::system(command.c_str());
        std::ifstream in(log);
        std::stringstream text;
        text << in.rdbuf();
        std::filesystem::remove(log);
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
    }

    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const std::filesystem::path p = m_dir / name;
        std::ofstream(p, std::ios::binary) << text;
        return p;
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
