#include "screens/gne/GneModelText.h"

namespace mtc::screens::gnefields {

std::string ModelText::english() const {
    std::string out;
    for (const char* p = form; *p; ++p) {
        const bool placeholder = p[0] == '%' && p[1] >= '1' && p[1] <= '9';
        const auto index = placeholder ? static_cast<std::size_t>(p[1] - '1') : args.size();
        if (index < args.size()) {
            out += args[index];
            ++p;
        } else {
            out += *p;
        }
    }
    return out;
}

std::string englishLines(const std::vector<ModelText>& texts) {
    std::string out;
    for (const ModelText& text : texts)
        out += text.english() + "\n";
    return out;
}

}  // namespace mtc::screens::gnefields
