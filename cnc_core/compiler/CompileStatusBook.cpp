#include "cnc_core/compiler/CompileStatusBook.h"

#include <functional>
#include <string>

namespace mtc::core {

CompileStatus CompileStatusBook::status(int process, int number, const Program& program,
                                        const CompilerOptions& options) const {
    if (!needsCompilation(program, options)) return CompileStatus::NotNeeded;
    const auto it = entries_.find({process, number});
    if (it == entries_.end() ||
        it->second.sourceHash != std::hash<std::string_view>{}(program.source.view()))
        return CompileStatus::NotCompiled;
    return it->second.status;
}

void CompileStatusBook::record(int process, int number, const Program& program,
                               const CompileResult& result) {
    entries_[{process, number}] = {std::hash<std::string_view>{}(program.source.view()),
                                   result.status};
}

}  // namespace mtc::core
