#include "cnc_core/machine/ZeroOffsetTable.h"

namespace mtc::core {

ZeroOffsetTable ZeroOffsetTable::build(const ProcessConfig& config, DiagnosticList& diagnostics) {
    ZeroOffsetTable table;
    for (const auto& offset : config.zeroOffsets) {
        const bool codeOk = offset.code.size() == 3 && offset.code[0] == 'G' &&
                            offset.code[1] == '5' && offset.code[2] >= '4' && offset.code[2] <= '9';
        if (!codeOk) {
            diagnostics.error("CFG_ZERO_OFFSET", {},
                              "process " + std::to_string(config.index) + ": zero offset '" +
                                  offset.code + "' is not G54..G59");
            continue;
        }
        const int code = 50 + (offset.code[2] - '0');
        for (const auto& [key, value] : offset.values) {
            const AxisDefinition d =
                key.size() == 1 ? definitionFromLetter(key[0]) : AxisDefinition::None;
            if (d == AxisDefinition::None || !table.set(code, d, value))
                diagnostics.error("CFG_ZERO_OFFSET", {},
                                  "process " + std::to_string(config.index) + ": " + offset.code +
                                      " column '" + key +
                                      "' is not an axis definition (X Y Z U V W A B C)");
        }
    }
    return table;
}

bool ZeroOffsetTable::set(int code, AxisDefinition definition, double offset) {
    if (code < 54 || code > 59 || definition == AxisDefinition::None) return false;
    rows_[static_cast<size_t>(code - 53)][static_cast<size_t>(definition)] = offset;
    return true;
}

}  // namespace mtc::core
