// libFuzzer entry of one target (MTC_FUZZ_TARGET, set per executable) with
// the number mutator: one mutation in four replaces a number of the input by
// an extreme one; the others are libFuzzer's own.
#include <cstdlib>
#include <cstring>
#include <string>

#include "FuzzTargets.h"
#include "NumberMutator.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t maxSize);

namespace {

const mtc::fuzz::FuzzTarget& target() {
    static const mtc::fuzz::FuzzTarget* found = mtc::fuzz::findFuzzTarget(MTC_FUZZ_TARGET);
    if (!found) std::abort();
    return *found;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    target().run(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t maxSize, unsigned int seed) {
    if (seed % 4 == 0) {
        std::string text(reinterpret_cast<const char*>(data), size);
        if (mtc::fuzz::replaceNumberByExtreme(text, seed / 4, maxSize)) {
            std::memcpy(data, text.data(), text.size());
            return text.size();
        }
    }
    return LLVMFuzzerMutate(data, size, maxSize);
}
