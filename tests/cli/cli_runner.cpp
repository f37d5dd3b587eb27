#include "cli_runner.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace sculptline::cli_test {
namespace {

// Far above any case here (each runs in milliseconds); only a hang reaches it.
constexpr auto kTimeLimit = std::chrono::seconds(20);

std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeFile(const std::string& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary);
    out << text;
}

struct ScratchDir {
    std::string path;
    ScratchDir()
    {
        std::string pattern = (std::filesystem::temp_directory_path() / "sculptline-cli-test-XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a scratch directory");
        path = pattern;
    }
    ~ScratchDir()
    {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

}  // namespace

std::string scratchPath(const std::string& name)
{
    static const ScratchDir dir;
    return dir.path + "/" + name;
}

CliResult runCli(const std::vector<std::string>& args, const std::string& stdinText)
{
    static int counter = 0;
    const std::string base = scratchPath("run" + std::to_string(++counter));
    const std::string in = base + ".in", out = base + ".out", err = base + ".err";
    writeFile(in, stdinText);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, in.c_str(), O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> argvStrings{SCULPTLINE_CLI_PATH};
    argvStrings.insert(argvStrings.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argvStrings) argv.push_back(a.data());
    argv.push_back(nullptr);

    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) throw std::runtime_error(std::string("cannot start ") + SCULPTLINE_CLI_PATH);

    CliResult result;
    int wstatus = 0;
    const auto deadline = std::chrono::steady_clock::now() + kTimeLimit;
    while (waitpid(pid, &wstatus, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &wstatus, 0);
            result.status = kTimedOut;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (result.status != kTimedOut) {
        result.status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -WTERMSIG(wstatus);
    }
    result.out = readFile(out);
    result.err = readFile(err);
    for (const auto& f : {in, out, err}) std::remove(f.c_str());
    return result;
}

json runOk(const std::string& subcommand, const json& input)
{
    const CliResult r = runCli({subcommand}, input.dump());
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    if (r.status != 0) return json::object();
    json out = json::parse(r.out);
    // Every output carries the computation time (../shared/interfaces.md).
    EXPECT_TRUE(out.contains("elapsed_ms") && out["elapsed_ms"].is_number() && out["elapsed_ms"].get<double>() >= 0)
        << r.out.substr(0, 200);
    return out;
}

std::string dataPath(const std::string& name)
{
    return std::string(SCULPTLINE_CLI_TEST_DATA) + "/" + name;
}

json loadData(const std::string& name)
{
    return json::parse(readFile(dataPath(name)));
}

std::vector<Eigen::Vector3d> pointsOf(const json& array)
{
    std::vector<Eigen::Vector3d> points;
    for (const auto& p : array) points.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    return points;
}

std::vector<double> linspace(double a, double b, int count)
{
    std::vector<double> v(count);
    for (int i = 0; i < count; ++i) v[i] = i + 1 == count ? b : a + (b - a) * i / (count - 1);
    return v;
}

}  // namespace sculptline::cli_test
