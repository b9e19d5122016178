#include "cnc_core/machine/MachineConfigReader.h"

#include <memory>
#include <unordered_map>

#include "cnc_core/machine/ConfigReport.h"
#include "cnc_core/machine/ConfigSections.h"
#include "cnc_core/machine/ConfigText.h"
#include "cnc_core/machine/ConfigWords.h"
#include "cnc_core/interp/MachineSink.h"  // kMaxAxes
#include "cnc_core/machine/ProcessAxes.h"

namespace mtc::core {
namespace {

constexpr std::string_view kEndMarker = "[end]";

/// Reads one configuration text line by line, one section reader at a time.
class Reader {
  public:
    Reader(MachineConfigReadResult& result, const MachineConfigReadOptions& options)
        : result_(result), options_(options), report_(options.fileName, result.diagnostics) {}

    void run(std::string_view text) {
        int lineNo = 0;
        std::size_t pos = 0;
        while (pos < text.size() && !report_.full()) {
            std::size_t nl = text.find('\n', pos);
            if (nl == std::string_view::npos) nl = text.size();
            report_.setLine(++lineNo);
            handleLine(text.substr(pos, nl - pos));
            pos = nl + 1;
        }
        closeSection();
        report_.setSection("");
        checkProcesses();
        if (options_.requireEndMarker && endLine_ == 0)
            report_.errorAt(lineNo, "CFG_TRUNCATED",
                            "the file does not end with the line " + std::string(kEndMarker) +
                                ": it may be cut off (an interrupted copy or save); see "
                                "docs/MACHINE-CONFIG.md");
        if (result_.config.processes.empty())
            report_.errorAt(0, "CFG_NO_PROCESS", "the configuration defines no process");
    }

  private:
    void handleLine(std::string_view raw) {
        const std::string_view text = trimConfigText(raw.substr(0, raw.find('#')));
        if (text.empty()) return;
        if (endLine_ != 0)
            return report_.errorAt(report_.line(), "CFG_SYNTAX",
                                   "text after " + std::string(kEndMarker) + " (line " +
                                       std::to_string(endLine_) + "): " + quotedValue(text),
                                   false);
        const std::size_t eq = text.find('=');
        const std::string_view key = trimConfigText(text.substr(0, eq));
        // Values are checked for control characters and bytes that are not
        // UTF-8 by their rules (so the refusal names key and range); what
        // has no rule is checked here. Messages quote with escapes (CF-005).
        if (!isPrintableText(text.front() == '[' || eq == std::string_view::npos ? text : key))
            return report_.error("CFG_SYNTAX",
                                 "the line contains control characters or bytes that are not "
                                 "UTF-8: " +
                                     quotedValue(text, 40));
        if (text.front() == '[') return openSection(text);
        if (eq == std::string_view::npos)
            return report_.error("CFG_SYNTAX", "expected 'key = value', got " + quotedValue(text));
        if (!section_)
            return report_.error("CFG_SYNTAX", "key " + quotedValue(key) + " outside any section");
        section_->line(key, trimConfigText(text.substr(eq + 1)));
    }

    void closeSection() {
        if (section_) section_->finish();
        section_.reset();
    }

    void openSection(std::string_view text) {
        closeSection();
        report_.setSection("");
        if (text.back() != ']') {
            section_ = makeSkippedSection(report_);
            return report_.error("CFG_SYNTAX", "section header without ']': " + quotedValue(text));
        }
        const std::vector<std::string_view> words =
            splitConfigWords(text.substr(1, text.size() - 2));
        std::string header = "[";
        for (std::string_view w : words)
            header += (header.size() > 1 ? " " : "") + std::string(w);
        header += "]";
        if (header == kEndMarker) return void(endLine_ = report_.line());
        const auto [first, inserted] = headers_.emplace(header, report_.line());
        if (!inserted) {
            section_ = makeSkippedSection(report_);
            return report_.error("CFG_DUPLICATE", header + " is given twice (first in line " +
                                                      std::to_string(first->second) + ")");
        }
        report_.setSection(header);
        section_ = makeSection(words);
        if (!section_) section_ = makeSkippedSection(report_);
    }

    /// The reader of the section `words` names, or nullptr after a report.
    std::unique_ptr<ConfigSectionReader> makeSection(const std::vector<std::string_view>& words) {
        if (words.size() == 1 && words[0] == "cell") return makeCellReader(report_, result_.config);
        if (words.size() < 2 || words[0] != "process") return unknownSection();
        const int number = sectionNumber(ConfigSection::Process, words[1]);
        if (number < 0) return nullptr;
        if (words.size() == 2) return openProcess(number);
        ProcessConfig* p = process(number);
        if (!p) {
            report_.error("CFG_PROCESS", "process " + std::to_string(number) +
                                             " used before its [process " +
                                             std::to_string(number) + "] section");
            return nullptr;
        }
        const std::string_view kind = words[2];
        if (words.size() == 4 && (kind == "axis" || kind == "spindle"))
            return openAxis(*p, words[3], kind == "spindle");
        if (words.size() == 4 && kind == "mgroup") return openMGroup(*p, words[3]);
        if (words.size() == 4 && kind == "page") return openPage(*p, words[3]);
        if (words.size() == 3 && kind == "tools") return makeToolsReader(report_, *p);
        if (words.size() == 3 && kind == "zero-offsets") return makeZeroOffsetsReader(report_, *p);
        if (words.size() == 3 && kind == "torque-model") return makeTorqueModelReader(report_, *p);
        return unknownSection();
    }

    std::unique_ptr<ConfigSectionReader> unknownSection() {
        std::string known;
        for (ConfigSection s : {ConfigSection::Cell, ConfigSection::Process, ConfigSection::Axis,
                                ConfigSection::Spindle, ConfigSection::MGroup,
                                ConfigSection::Tools, ConfigSection::ZeroOffsets,
                                ConfigSection::TorqueModel, ConfigSection::Page})
            known += (known.empty() ? "" : " ") + std::string(configSectionName(s));
        report_.error("CFG_SECTION", "unknown section; known: " + known);
        return nullptr;
    }

    /// The number of a section header word ("0" of [process 0]) checked
    /// against the "(number)" rule of `kind`; -1 after a report.
    int sectionNumber(ConfigSection kind, std::string_view word) {
        const ConfigRule* rule = findConfigRule(kind, "(number)");
        ConfigValue value;
        std::string problem;
        if (checkConfigValue(*rule, word, value, problem)) return static_cast<int>(value.number);
        report_.error(kind == ConfigSection::Process ? "CFG_PROCESS"
                      : kind == ConfigSection::Page  ? "CFG_PAGE"
                                                     : "CFG_MGROUP",
                      "number " + quotedValue(word) + " " + problem +
                          "; allowed: " + configRangeText(*rule));
        return -1;
    }

    ProcessConfig* process(int number) {
        for (auto& p : result_.config.processes)
            if (p.index == number) return &p;
        return nullptr;
    }

    std::unique_ptr<ConfigSectionReader> openProcess(int number) {
        result_.config.processes.push_back({});
        result_.config.processes.back().index = number;
        result_.config.processes.back().line = report_.line();
        return makeProcessReader(report_, result_.config.processes.back());
    }

    std::unique_ptr<ConfigSectionReader> openAxis(ProcessConfig& p, std::string_view name,
                                                  bool spindle) {
        if (p.axes.size() >= static_cast<std::size_t>(kMaxAxes)) {
            report_.error("CFG_AXIS_COUNT", "more than " + std::to_string(kMaxAxes) +
                                                " axes and spindles in process " +
                                                std::to_string(p.index));
            return nullptr;
        }
        for (const AxisConfig& other : p.axes)
            if (other.name == name) {  // [process N axis X] and [process N spindle X]
                report_.error("CFG_AXIS", "axis " + std::string(name) + " is defined twice");
                return nullptr;
            }
        AxisConfig axis;
        axis.name = std::string(name);
        axis.kind = spindle ? AxisKind::Spindle : AxisKind::Linear;
        axis.line = report_.line();
        if (spindle) axis.definitions = {axis.name};
        p.axes.push_back(std::move(axis));
        return makeAxisReader(report_, p.axes.back());
    }

    std::unique_ptr<ConfigSectionReader> openMGroup(ProcessConfig& p, std::string_view word) {
        const int number = sectionNumber(ConfigSection::MGroup, word);
        if (number < 0) return nullptr;
        p.mGroups.push_back({});
        p.mGroups.back().number = number;
        return makeMGroupReader(report_, p, p.mGroups.size() - 1);
    }

    std::unique_ptr<ConfigSectionReader> openPage(ProcessConfig& p, std::string_view word) {
        const int number = sectionNumber(ConfigSection::Page, word);
        if (number < 0) return nullptr;
        p.userPages.push_back({});
        p.userPages.back().number = number;
        return makePageReader(report_, p.userPages.back());
    }

    /// The checks over all axes of a process (names, definitions, duplicates,
    /// count): ProcessAxes::build, the rule the interpreter applies too.
    void checkProcesses() {
        for (const ProcessConfig& p : result_.config.processes) {
            DiagnosticList axes;
            ProcessAxes::build(p, axes);
            report_.adopt(axes);
        }
    }

    MachineConfigReadResult& result_;
    const MachineConfigReadOptions& options_;
    ConfigReport report_;
    std::unique_ptr<ConfigSectionReader> section_;
    std::unordered_map<std::string, int> headers_;  ///< section header -> line
    int endLine_ = 0;                               ///< line of [end] (0 = not seen)
};

}  // namespace

MachineConfigReadResult readMachineConfig(std::string_view text,
                                          const MachineConfigReadOptions& options) {
    MachineConfigReadResult result;
    Reader(result, options).run(text);
    return result;
}

}  // namespace mtc::core
