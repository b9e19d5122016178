#pragma once

#include <cstddef>

namespace mtc::core::messages {

/// One row of the German message table: a diagnostic code and its German
/// brief message (docs/DECISIONS.md D-023).
struct MessageEntry {
    const char* code;
    const char* german;
};

/// A part of the table: `size` rows from `entries`.
struct MessageTable {
    const MessageEntry* entries;
    std::size_t size;
};

/// Reading programs: files, parser, interpreter, planes and transformations,
/// MDI.
MessageTable programMessages();
/// The NC compiler, look-ahead, radius compensation, GNE, user compilers.
MessageTable compilerMessages();
/// Alarms, prompts and messages without a diagnostic: the machine control
/// keys, jogging, Start, GAX, a held program, MDI (D-025, D-026).
MessageTable alarmMessages();
/// Machine configuration, machine data, tool and offset files, adaptive feed
/// control, NC program restart, material removal.
MessageTable setupMessages();

}  // namespace mtc::core::messages
