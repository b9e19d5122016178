// Word splitting, axis table and plane axes of the look-ahead analysis.
#include <algorithm>

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/lookahead/LookAheadScan.h"

namespace mtc::core::lookahead {
namespace detail {
namespace {

std::string trimmed(std::string_view text) {
    while (!text.empty() && text.front() == ' ')
        text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ')
        text.remove_suffix(1);
    return std::string(text);
}

}  // namespace

BlockWords splitWords(const CompileBlock& block, const Program& program, const Block& parsed) {
    BlockWords out;
    const std::string_view text(block.text);
    const std::size_t commentAt = commentOffset(text);
    out.comment = std::string(text.substr(commentAt));
    const std::size_t shift = block.prefix.size() + 1;  // columns count the prefix, 1-based
    std::vector<std::size_t> starts;
    for (std::uint32_t w = parsed.firstWord; w < parsed.firstWord + parsed.wordCount; ++w) {
        const std::size_t column = program.words[w].column;
        starts.push_back(column >= shift ? std::min(column - shift, commentAt) : 0);
    }
    out.lead = trimmed(text.substr(0, starts.empty() ? commentAt : starts.front()));
    for (std::size_t k = 0; k < starts.size(); ++k) {
        const std::size_t end = k + 1 < starts.size() ? starts[k + 1] : commentAt;
        out.raw.push_back(trimmed(text.substr(starts[k], end > starts[k] ? end - starts[k] : 0)));
    }
    return out;
}

std::string joinWords(const std::string& lead, const std::vector<std::string>& words,
                      const std::string& comment) {
    std::string text = lead;
    for (const std::string& word : words) {
        if (word.empty()) continue;
        if (!text.empty()) text += ' ';
        text += word;
    }
    if (!comment.empty()) {
        if (!text.empty()) text += ' ';
        text += comment;
    }
    return text;
}

PlaneAxes planeAxes(int plane, const std::vector<char>& definitions) {
    char first = 'X', second = 'Y';
    if (plane == 18) first = 'Z', second = 'X';
    if (plane == 19) first = 'Y', second = 'Z';
    PlaneAxes axes;
    for (std::size_t i = 0; i < definitions.size(); ++i) {
        if (definitions[i] == first && axes.first < 0) axes.first = static_cast<int>(i);
        if (definitions[i] == second && axes.second < 0) axes.second = static_cast<int>(i);
    }
    return axes;
}

}  // namespace detail

AxisLimits axisLimitsOf(const ProcessConfig* process) {
    AxisLimits limits;
    std::vector<AxisConfig> axes;
    if (process) {
        for (const AxisConfig& axis : process->axes)
            if (axis.kind != AxisKind::Spindle && axes.size() < kMaxLookAheadAxes)
                axes.push_back(axis);
    } else {
        for (const char* name : {"X", "Y", "Z"}) {
            axes.emplace_back();
            axes.back().name = name;
        }
    }
    const int n = static_cast<int>(axes.size());
    limits.maxVelocity = AxisVector::Zero(n);
    limits.maxAcceleration = AxisVector::Zero(n);
    for (int i = 0; i < n; ++i) {
        limits.names.push_back(axes[static_cast<std::size_t>(i)].name);
        limits.maxVelocity[i] = axes[static_cast<std::size_t>(i)].maxVelocity;
        limits.maxAcceleration[i] = axes[static_cast<std::size_t>(i)].maxAcceleration;
    }
    return limits;
}

}  // namespace mtc::core::lookahead
