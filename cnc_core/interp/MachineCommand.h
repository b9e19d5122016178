#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "cnc_core/language/Diagnostic.h"

/// The NC commands the interpreter hands to the machine (seed 000, 5.4), as
/// typed data: the interpreter reads the programmed text once
/// (readMachineCommand) and no receiver parses it again.
namespace mtc::core {

/// One value per keyword of KeywordClass::Command (language/Keywords.cpp).
enum class CommandKeyword : std::uint8_t {
    // Tool storage unit motion and its interrogation (MRV: see ToolStorageCommand).
    MTP,
    MMP,
    MFP,
    MHP,
    MOP,
    MRF,
    MRY,
    MRV,
    // Synchronous tool transfer.
    TCH,
    TMS,
    TSM,
    // Tool checks (spindle 1 empty, magazine place 1) and tool load.
    TSE,
    TPE,
    TLD,
    // Position strobe of analog drives.
    PMP,
    NMP,
    // Axis transfer.
    GAX,
    FAX,
    // Drive data, idle thrust measurement, acceleration.
    AXD,
    ITM,
    ACC,
    // Process control, synchronisation and events.
    DP,
    SP,
    RP,
    AP,
    WP,
    LP,
    POK,
    WES,
    WER,
    SE,
    RE,
    BRJ,
};

/// "TCH" of CommandKeyword::TCH.
std::string_view keywordName(CommandKeyword keyword);
/// The command keyword named `name` exactly, if there is one.
std::optional<CommandKeyword> commandKeyword(std::string_view name);

/// GAX / FAX of one process: request an axis or relinquish it.
enum class AxisTransferKind { Get, Free };

// What a command asks of the machine, one alternative per family the seeds
// treat alike (seed 000, 5.4: which of them the computing process performs).

/// MTP, MMP, MFP, MHP, MOP, MRF: move the tool storage unit; MRY: wait until
/// it has moved. MRV is written where MRY is meant in the turning-centre
/// example of seed 000, 7.2; it is treated like MRY.
struct ToolStorageCommand {};
/// TCH, TMS (magazine to spindle) and TSM (spindle to magazine) of tool
/// spindle `spindle` (the SPI argument, 1..4; 1 when not given).
struct ToolTransferCommand {
    int spindle = 1;
};
/// TSE (is spindle 1 empty), TPE (is magazine place 1 in position).
struct ToolCheckCommand {};
/// PMP, NMP: take the actual position of analog drives.
struct PositionStrobeCommand {};
/// GAX / FAX of the named axes (upper case, e.g. "X1"; empty when the
/// arguments name none, which the interpreter refuses with a cell).
struct AxisTransferCommand {
    AxisTransferKind kind = AxisTransferKind::Get;
    std::vector<std::string> axes;
};
/// TLD, AXD, ITM, ACC and the process commands (DP ... BRJ): the SPS and the
/// drives act on them; the simulated machine only synchronises with them.
struct SpsCommand {};

using CommandAction = std::variant<ToolStorageCommand, ToolTransferCommand, ToolCheckCommand,
                                   PositionStrobeCommand, AxisTransferCommand, SpsCommand>;

/// One command of a block, as the machine receives it.
struct MachineCommand {
    SourceLocation where;
    CommandKeyword keyword = CommandKeyword::SP;
    CommandAction action;
    /// The arguments as programmed ("(1,1)"): shown in transcripts and on
    /// the SPS side only, never read by a receiver (the action carries what
    /// the NC itself uses).
    std::string arguments;
};

/// A command word's text ("TCH(1,2)") and its arguments as the parser keeps
/// them ("(1,2)") as a typed command, or nullopt when the text names no
/// command keyword. A GAX / FAX that names no axis gets an empty list.
std::optional<MachineCommand> readMachineCommand(std::string_view text, std::string_view arguments);

/// The axes of an axis transfer command: keyword "GAX" / "FAX" (else false)
/// and its arguments as the parser keeps them (the rest of the block):
/// "(X1)" or "(X1, Z2) AXD ..." give the list in the parentheses, "X1 ..."
/// the first word; names are upper case. False as well when no axis is named.
bool parseAxisTransfer(const std::string& keyword, const std::string& arguments,
                       AxisTransferKind& kind, std::vector<std::string>& axes);

/// "TCH ((1,1))": the one text form of a command (interpreter transcripts).
std::string commandText(const MachineCommand& command);

/// False for what the computing process of an NC program restart does not
/// perform (seed 000, 5.4): tool storage motion and MRY, the synchronous
/// tool transfers, TSE / TPE and PMP / NMP.
bool performedWhileComputing(const MachineCommand& command);

}  // namespace mtc::core
