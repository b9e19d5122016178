#include "cnc_core/interp/MachineCommand.h"

#include <array>
#include <cctype>

namespace mtc::core {

namespace {

// Order of CommandKeyword.
constexpr std::array<std::string_view, 33> kNames = {
    "MTP", "MMP", "MFP", "MHP", "MOP", "MRF", "MRY", "MRV", "TCH", "TMS", "TSM",
    "TSE", "TPE", "TLD", "PMP", "NMP", "GAX", "FAX", "AXD", "ITM", "ACC", "DP",
    "SP",  "RP",  "AP",  "WP",  "LP",  "POK", "WES", "WER", "SE",  "RE",  "BRJ"};
static_assert(static_cast<std::size_t>(CommandKeyword::BRJ) + 1 == kNames.size());

/// "(2,1)" -> 1 (the SPI argument), 1 when not given; clamped to 1..4.
int spindleArgument(std::string_view args) {
    const auto comma = args.find(',');
    if (comma == std::string_view::npos) return 1;
    int spindle = 0;
    std::size_t first = comma + 1;
    while (first < args.size() && args[first] == ' ')
        ++first;  // "TCH(1, 2)": blanks after the comma
    for (std::size_t i = first; i < args.size() && args[i] >= '0' && args[i] <= '9' && spindle < 10;
         ++i)
        spindle = spindle * 10 + (args[i] - '0');
    return spindle >= 1 && spindle <= 4 ? spindle : 1;
}

}  // namespace

std::string_view keywordName(CommandKeyword keyword) {
    const auto index = static_cast<std::size_t>(keyword);
    return index < kNames.size() ? kNames[index] : "?";
}

std::optional<CommandKeyword> commandKeyword(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i)
        if (kNames[i] == name) return static_cast<CommandKeyword>(i);
    return std::nullopt;
}

std::optional<MachineCommand> readMachineCommand(std::string_view text,
                                                 std::string_view arguments) {
    const std::optional<CommandKeyword> keyword =
        commandKeyword(text.substr(0, text.find_first_of(" (=")));
    if (!keyword) return std::nullopt;
    MachineCommand command;
    command.keyword = *keyword;
    command.arguments = std::string(arguments);
    using K = CommandKeyword;
    switch (*keyword) {
        case K::MTP:
        case K::MMP:
        case K::MFP:
        case K::MHP:
        case K::MOP:
        case K::MRF:
        case K::MRY:
        case K::MRV:
            command.action = ToolStorageCommand{};
            break;
        case K::TCH:
        case K::TMS:
        case K::TSM:
            command.action = ToolTransferCommand{spindleArgument(arguments)};
            break;
        case K::TSE:
        case K::TPE:
            command.action = ToolCheckCommand{};
            break;
        case K::PMP:
        case K::NMP:
            command.action = PositionStrobeCommand{};
            break;
        case K::GAX:
        case K::FAX: {
            AxisTransferCommand transfer;  // no axis named: an empty list
            parseAxisTransfer(std::string(keywordName(*keyword)), command.arguments, transfer.kind,
                              transfer.axes);
            command.action = std::move(transfer);
            break;
        }
        default:
            command.action = SpsCommand{};
            break;
    }
    return command;
}

bool parseAxisTransfer(const std::string& keyword, const std::string& arguments,
                       AxisTransferKind& kind, std::vector<std::string>& axes) {
    if (keyword == "GAX")
        kind = AxisTransferKind::Get;
    else if (keyword == "FAX")
        kind = AxisTransferKind::Free;
    else
        return false;
    axes.clear();
    // The parser keeps the rest of the block as the command's arguments: the
    // axes are the list in the parentheses right after the keyword, or the
    // first word when there are none.
    const std::size_t first = arguments.find_first_not_of(" \t");
    if (first == std::string::npos) return false;
    std::string list;
    if (arguments[first] == '(') {
        const std::size_t close = arguments.find(')', first);
        list = arguments.substr(first + 1, close == std::string::npos ? close : close - first - 1);
    } else {
        list = arguments.substr(first, arguments.find_first_of(" \t", first) - first);
    }
    std::string name;
    for (char c : list + ",") {
        if (c == ',') {
            if (!name.empty()) axes.push_back(name);
            name.clear();
        } else if (!std::isspace(static_cast<unsigned char>(c))) {
            name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        }
    }
    return !axes.empty();
}

std::string commandText(const MachineCommand& command) {
    return std::string(keywordName(command.keyword)) + " (" + command.arguments + ")";
}

bool performedWhileComputing(const MachineCommand& command) {
    return std::holds_alternative<AxisTransferCommand>(command.action) ||
           std::holds_alternative<SpsCommand>(command.action);
}

}  // namespace mtc::core
