#include "cnc_core/compiler/CommandLine.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace mtc::core {

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

/// Characters the shell would treat as operators or expansions outside quotes.
bool isShellOperator(char c) {
    return c == ';' || c == '|' || c == '&' || c == '<' || c == '>' || c == '`' || c == '$' ||
           c == '(' || c == ')' || c == '\n' || c == '*' || c == '?' || c == '~';
}

double secondsSince(const timespec& start) {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return static_cast<double>(now.tv_sec - start.tv_sec) +
           static_cast<double>(now.tv_nsec - start.tv_nsec) / 1e9;
}

}  // namespace

bool splitCommandLine(std::string_view command, std::vector<std::string>& words,
                      std::string& problem) {
    words.clear();
    std::string word;
    bool inWord = false;
    for (std::size_t i = 0; i < command.size(); ++i) {
        const char c = command[i];
        if (isBlank(c)) {
            if (inWord) words.push_back(word);
            word.clear();
            inWord = false;
            continue;
        }
        inWord = true;
        if (c == '\'') {  // everything up to the next ' is literal
            const std::size_t end = command.find('\'', i + 1);
            if (end == std::string_view::npos) return problem = "a ' is not closed", false;
            word.append(command.substr(i + 1, end - i - 1));
            i = end;
        } else if (c == '"') {  // \" \\ \$ \` are escapes, the rest is literal
            std::size_t k = i + 1;
            for (; k < command.size() && command[k] != '"'; ++k) {
                if (command[k] == '\\' && k + 1 < command.size() &&
                    std::strchr("\"\\$`", command[k + 1]) != nullptr)
                    ++k;
                else if (command[k] == '$' || command[k] == '`')
                    return problem = std::string("'") + command[k] +
                                     "' inside \"...\": commands run without a shell, so "
                                     "nothing is expanded (use '...' or \\" +
                                     command[k] + ")",
                           false;
                word += command[k];
            }
            if (k >= command.size()) return problem = "a \" is not closed", false;
            i = k;
        } else if (c == '\\') {
            if (i + 1 >= command.size()) return problem = "the command ends with a \\", false;
            word += command[++i];
        } else if (isShellOperator(c)) {
            return problem = std::string("'") + c +
                             "' outside quotes: commands run without a shell, so shell "
                             "operators, variables and patterns are not available (write a "
                             "script, or quote the character)",
                   false;
        } else {
            word += c;
        }
    }
    if (inWord) words.push_back(word);
    if (words.empty()) return problem = "the command is empty", false;
    return true;
}

CommandOutcome runCommand(const std::vector<std::string>& arguments, double timeoutSeconds) {
    CommandOutcome outcome;
    if (arguments.empty()) return outcome.problem = "no command", outcome;
    std::vector<char*> argv;
    for (const std::string& a : arguments)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t child = 0;
    const int spawned = ::posix_spawnp(&child, argv[0], nullptr, nullptr, argv.data(), environ);
    if (spawned != 0) {
        outcome.problem = "cannot start '" + arguments[0] + "': " + std::strerror(spawned);
        return outcome;
    }
    outcome.started = true;
    timespec start{};
    clock_gettime(CLOCK_MONOTONIC, &start);
    int status = 0;
    for (;;) {
        const pid_t done = ::waitpid(child, &status, WNOHANG);
        if (done == child) break;
        if (done < 0 && errno != EINTR) {
            outcome.problem = std::string("lost the command: ") + std::strerror(errno);
            return outcome;
        }
        if (secondsSince(start) > timeoutSeconds) {
            ::kill(child, SIGKILL);
            ::waitpid(child, &status, 0);
            outcome.timedOut = true;
            outcome.problem = "did not finish within " +
                              std::to_string(static_cast<int>(timeoutSeconds)) + " s and was stopped";
            return outcome;
        }
        const timespec pause{0, 5 * 1000 * 1000};  // 5 ms
        nanosleep(&pause, nullptr);
    }
    if (WIFEXITED(status)) {
        outcome.exitStatus = WEXITSTATUS(status);
        // posix_spawnp reports a program it cannot find as exit status 127.
        if (outcome.exitStatus == 127)
            outcome.problem = "'" + arguments[0] + "' was not found or could not be run";
    } else {
        outcome.problem = "was ended by signal " + std::to_string(WTERMSIG(status));
    }
    return outcome;
}

}  // namespace mtc::core
