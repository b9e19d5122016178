// The coverage line of the restart verifier (RestartVerifier.h).
#include <map>
#include <string>

#include "cnc_core/restart/RestartVerifier.h"

namespace mtc::core {

namespace {

/// "1,204"
std::string grouped(std::uint64_t value) {
    std::string digits = std::to_string(value);
    for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3)
        digits.insert(static_cast<std::size_t>(i), ",");
    return digits;
}

/// "N0017", "N0017 (pass 2)", "P99 N0004" (outside the main program).
std::string targetName(const VerifiedTarget& t) {
    std::string name =
        t.where.block.empty() ? "line " + std::to_string(t.where.line) : t.where.block;
    if (t.selection.target.program != t.selection.mainProgram)
        name = "P" + std::to_string(t.selection.target.program) + " " + name;
    if (t.selection.runs > 1) name += " (pass " + std::to_string(t.selection.runs) + ")";
    return name;
}

/// What a difference says about the target, as a phrase of the coverage line.
std::string phrase(const StateDifference& d, bool cutting) {
    if (cutting && d.what == "g1" && d.numeric && d.actual == 0) return "leave G0 active";
    return (cutting ? "leave " : "compute ") + d.label + " wrong";
}

}  // namespace

std::string VerifyReport::coverageLine() const {
    std::string line =
        grouped(reestablished) + " of " + grouped(targets) + " targets re-established";
    // phrase -> target names, in the order the targets came
    std::vector<std::pair<std::string, std::vector<std::string>>> groups;
    auto add = [&groups](const std::string& key, const std::string& name) {
        for (auto& [k, names] : groups)
            if (k == key) {
                if (names.empty() || names.back() != name) names.push_back(name);
                return;
            }
        groups.push_back({key, {name}});
    };
    std::uint64_t forbidden = 0;
    for (const VerifiedTarget& t : problems) {
        const std::string name = targetName(t);
        if (t.outcome == TargetOutcome::NotSelectable) {
            ++forbidden;
            continue;
        }
        if (t.outcome == TargetOutcome::Failed) {
            std::string code = "an error";
            for (const Diagnostic& d : t.diagnostics.items())
                if (d.severity == Severity::Error) {
                    code = d.code;
                    break;
                }
            add("fail with " + code, name);
        }
        for (const StateDifference& d : t.computed)
            add(phrase(d, false), name);
        for (const StateDifference& d : t.cutting)
            add(phrase(d, true), name);
    }
    constexpr std::size_t kNamesShown = 8;
    for (const auto& [what, names] : groups) {
        line += "; " + grouped(names.size()) + " " + what + ": ";
        for (std::size_t i = 0; i < names.size() && i < kNamesShown; ++i)
            line += (i ? ", " : "") + names[i];
        if (names.size() > kNamesShown) line += ", …";
    }
    if (forbidden > 0)
        line += "; " + grouped(forbidden) + " arrivals are no target (cycle, 11th level)";
    if (beyondPasses > 0)
        line += "; " + grouped(beyondPasses) + " arrivals after the last verified pass";
    if (!complete) line += "; the run did not reach the program end";
    return line;
}

}  // namespace mtc::core
