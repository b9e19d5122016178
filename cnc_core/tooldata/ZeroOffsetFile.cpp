#include "cnc_core/tooldata/ZeroOffsetFile.h"

namespace mtc::core {

int zeroOffsetCode(std::string_view word) {
    if (word.size() == 3 && word[0] == 'G' && word[1] == '5' && word[2] >= '4' && word[2] <= '9')
        return 50 + (word[2] - '0');
    return 0;
}

std::vector<AxisDefinition> zeroOffsetColumns(const ProcessConfig& process,
                                              const ZeroOffsetTable& table) {
    std::vector<AxisDefinition> columns;
    for (int d = 0; d < kDefinitionCount; ++d) {
        const auto definition = static_cast<AxisDefinition>(d);
        bool used = false;
        for (const AxisConfig& axis : process.axes)
            for (const std::string& name : axis.definitions)
                used = used || (name.size() == 1 && definitionFromLetter(name[0]) == definition);
        for (int code = 54; code <= 59; ++code)
            used = used || table.value(code, definition) != 0.0;
        if (used) columns.push_back(definition);
    }
    return columns;
}

bool applyOffsetValue(DataFileText& text, int line, int code, const std::string& column,
                      const std::string& value, ZeroOffsetTable& table) {
    const AxisDefinition d =
        column.size() == 1 ? definitionFromLetter(column[0]) : AxisDefinition::None;
    if (d == AxisDefinition::None) {
        text.refuse(line, column, value, "not an axis definition (allowed X Y Z U V W A B C)");
        return false;
    }
    double v = 0.0;
    if (!text.number(line, column, value, -kMaxZeroOffset, kMaxZeroOffset, "mm or degrees", v))
        return false;
    table.set(code, d, v);
    return true;
}

std::string formatOffsetFile(const ZeroOffsetTables& tables) {
    std::string out =
        "# MTC200 simulator: zero offsets G54..G59 (docs/TOOL-DATA.md). Columns are axis "
        "definitions.\n";
    out += dataFrameHeader(kOffsetFileFormat);
    std::size_t records = 0;
    for (const auto& [process, table] : tables) {
        out += "[process " + std::to_string(process) + "]\n";
        for (int code = 54; code <= 59; ++code) {
            out += "G" + std::to_string(code);
            for (int d = 0; d < kDefinitionCount; ++d) {
                const auto definition = static_cast<AxisDefinition>(d);
                const double v = table.value(code, definition);
                if (v != 0.0)
                    out +=
                        std::string(" ") + definitionLetter(definition) + "=" + formatDataNumber(v);
            }
            out += '\n';
            ++records;
        }
    }
    out += "end = " + std::to_string(records) + "\n";
    return out;
}

bool parseOffsetFile(std::string_view text, const std::string& fileName, ZeroOffsetTables& tables,
                     DiagnosticList& diagnostics) {
    DataFileText reader(fileName, diagnostics, "OFFSET_FILE");
    ZeroOffsetTables read;
    std::map<int, unsigned> seenCodes;  // per process: bit of each code given
    auto record = [&](int line, int process, std::string_view body) {
        const std::vector<std::string_view> words = wordsOf(body);
        const int code = zeroOffsetCode(words.front());
        if (code == 0) {
            reader.refuse(line, "code", std::string(words.front()), "allowed G54 .. G59");
            return;
        }
        unsigned& seen = seenCodes[process];
        if (seen & (1u << (code - 54))) {
            reader.refuse(line, "code", std::string(words.front()), "given twice in this process");
            return;
        }
        seen |= 1u << (code - 54);
        unsigned columns = 0;
        for (std::size_t i = 1; i < words.size(); ++i) {
            const std::size_t eq = words[i].find('=');
            const std::string column(words[i].substr(0, eq));
            if (eq == std::string_view::npos) {
                reader.refuse(line, column, "", "expected COLUMN=value");
                continue;
            }
            const std::string value(words[i].substr(eq + 1));
            const AxisDefinition d =
                column.size() == 1 ? definitionFromLetter(column[0]) : AxisDefinition::None;
            if (d != AxisDefinition::None && (columns & (1u << static_cast<int>(d)))) {
                reader.refuse(line, column, value, "column given twice in one record");
                continue;
            }
            if (d != AxisDefinition::None) columns |= 1u << static_cast<int>(d);
            applyOffsetValue(reader, line, code, column, value, read[process]);
        }
    };
    auto section = [&](int process) { read[process]; };
    if (!readDataFrame(text, kOffsetFileFormat, reader, record, section) || reader.failed())
        return false;
    tables = std::move(read);
    return true;
}

}  // namespace mtc::core
