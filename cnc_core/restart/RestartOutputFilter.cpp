#include "cnc_core/restart/RestartOutputFilter.h"

#include <array>
#include <string_view>

namespace mtc::core {

bool RestartOutputFilter::suppressed(const std::string& keyword) {
    // MRV: the turning-centre example of seed 000, 7.2 writes it where MRY
    // (wait for the tool storage) is meant; the parser knows it as a command.
    static constexpr std::array<std::string_view, 15> kNotPerformed = {
        "PMP", "NMP", "TSE", "TPE", "MFP", "MHP", "MMP", "MOP",
        "MRF", "MTP", "MRY", "MRV", "TCH", "TMS", "TSM"};
    for (std::string_view k : kNotPerformed)
        if (keyword == k) return true;
    return false;
}

void RestartOutputFilter::command(const SourceLocation& where, const std::string& keyword,
                                  const std::string& arguments) {
    if (suppressed(keyword)) {
        ++suppressed_;
        return;
    }
    ++passed_;
    sps_.command(where, keyword, arguments);
}

}  // namespace mtc::core
