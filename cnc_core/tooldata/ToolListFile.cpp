#include "cnc_core/tooldata/ToolListFile.h"

#include <cstring>

namespace mtc::core {

namespace {

constexpr double kMaxRadius = 999.99999;  // seed 001 ch. 6, TL_RADIUS
constexpr double kMaxWear = 99.99999;
constexpr double kMaxLength = 9999.9999;

struct NumberKey {
    const char* key;
    double ToolEdge::*field;
    double low, high;
    const char* unit;
};

const NumberKey kNumberKeys[] = {
    {"radius", &ToolEdge::radius, 0.0, kMaxRadius, "mm"},
    {"radius_wear", &ToolEdge::radiusWear, -kMaxWear, kMaxWear, "mm"},
    {"l1", &ToolEdge::length1, -kMaxLength, kMaxLength, "mm"},
    {"l2", &ToolEdge::length2, -kMaxLength, kMaxLength, "mm"},
    {"l3", &ToolEdge::length3, -kMaxLength, kMaxLength, "mm"},
    {"l1_wear", &ToolEdge::length1Wear, -kMaxWear, kMaxWear, "mm"},
    {"l2_wear", &ToolEdge::length2Wear, -kMaxWear, kMaxWear, "mm"},
    {"l3_wear", &ToolEdge::length3Wear, -kMaxWear, kMaxWear, "mm"},
    {"corner_angle", &ToolEdge::cornerAngle, 0.0, 180.0, "degrees"},
    {"setting_angle", &ToolEdge::settingAngle, 0.0, 360.0, "degrees"},
};

bool validName(const std::string& name) {
    if (name.empty() || name.size() > 24) return false;
    for (char c : name)
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
              c == '_' || c == '-' || c == '.'))
            return false;
    return true;
}

/// "T12" -> 12 and "E3" -> 3 with their ranges.
bool tagNumber(DataFileText& text, int line, std::string_view word, char letter, long long high,
               long long& out) {
    const std::string value(word);
    if (word.size() < 2 || word[0] != letter) {
        text.refuse(line, std::string(1, letter), value,
                    std::string("expected ") + letter + "<number>");
        return false;
    }
    return text.integer(line, std::string(1, letter), value.substr(1), 1, high, out);
}

void appendRecord(std::string& out, const Tool& tool, const ToolEdge& e) {
    out += "T" + std::to_string(tool.number) + " E" + std::to_string(e.edge);
    for (const NumberKey& k : kNumberKeys)
        out += std::string(" ") + k.key + "=" + formatDataNumber(e.*(k.field));
    out += " orientation=" + std::to_string(e.orientation);
    if (!tool.name.empty()) out += " name=" + tool.name;
    out += '\n';
}

}  // namespace

std::string toolValueRange(const std::string& key) {
    for (const NumberKey& k : kNumberKeys)
        if (key == k.key)
            return formatDataNumber(k.low) + " .. " + formatDataNumber(k.high) + " " + k.unit;
    if (key == "orientation") return "0 .. 9";
    if (key == "name") return "1..24 of A-Z a-z 0-9 _ - .";
    return {};
}

const char* toolKeysHelp() {
    return "radius (0..999.99999 mm), radius_wear (-99.99999..99.99999 mm), l1 l2 l3 "
           "(-9999.9999..9999.9999 mm), l1_wear l2_wear l3_wear (-99.99999..99.99999 mm), "
           "orientation (0..9), corner_angle (0..180 degrees), setting_angle (0..360 degrees), "
           "name (1..24 of A-Z a-z 0-9 _ - .)";
}

bool applyToolValue(DataFileText& text, int line, const std::string& key, const std::string& value,
                    ToolEdge& edge, std::string& name) {
    for (const NumberKey& k : kNumberKeys)
        if (key == k.key)
            return text.number(line, key, value, k.low, k.high, k.unit, edge.*(k.field));
    if (key == "orientation") {
        long long v = 0;
        if (!text.integer(line, key, value, 0, 9, v)) return false;
        edge.orientation = static_cast<int>(v);
        return true;
    }
    if (key == "name") {
        if (!validName(value)) {
            text.refuse(line, key, value, "allowed 1..24 characters of A-Z a-z 0-9 _ - .");
            return false;
        }
        name = value;
        return true;
    }
    text.refuse(line, key, value, std::string("unknown key; allowed: ") + toolKeysHelp());
    return false;
}

std::string formatToolFile(const ToolLists& lists) {
    std::string out = "# MTC200 simulator: tool lists (docs/TOOL-DATA.md). One line per edge.\n";
    out += dataFrameHeader(kToolFileFormat);
    std::size_t records = 0;
    for (const auto& [process, list] : lists) {
        out += "[process " + std::to_string(process) + "]\n";
        for (const Tool& tool : list.tools())
            for (const ToolEdge& edge : tool.edges) {
                appendRecord(out, tool, edge);
                ++records;
            }
    }
    out += "end = " + std::to_string(records) + "\n";
    return out;
}

bool parseToolFile(std::string_view text, const std::string& fileName, ToolLists& lists,
                   DiagnosticList& diagnostics) {
    DataFileText reader(fileName, diagnostics, "TOOL_FILE");
    ToolLists read;
    auto record = [&](int line, int process, std::string_view body) {
        const std::vector<std::string_view> words = wordsOf(body);
        long long t = 0, e = 0;
        if (words.size() < 2 || !tagNumber(reader, line, words[0], 'T', kMaxToolNumber, t) ||
            !tagNumber(reader, line, words[1], 'E', kMaxEdgeNumber, e))
            return;
        ToolEdge edge;
        edge.edge = static_cast<int>(e);
        std::string name;
        std::vector<std::string> given;
        for (std::size_t i = 2; i < words.size(); ++i) {
            const std::size_t eq = words[i].find('=');
            const std::string key(words[i].substr(0, eq));
            const std::string value(eq == std::string_view::npos ? "" : words[i].substr(eq + 1));
            if (eq == std::string_view::npos) {
                reader.refuse(line, key, "", "expected key=value");
                continue;
            }
            bool twice = false;
            for (const std::string& g : given)
                twice = twice || g == key;
            if (twice) {
                reader.refuse(line, key, value, "key given twice in one record");
                continue;
            }
            given.push_back(key);
            applyToolValue(reader, line, key, value, edge, name);
        }
        ToolList& list = read[process];
        if (list.edge(static_cast<int>(t), edge.edge)) {
            reader.refuseLine(line, "T" + std::to_string(t) + " E" + std::to_string(e) +
                                        " is given twice in process " + std::to_string(process));
            return;
        }
        const Tool* tool = list.find(static_cast<int>(t));
        if (tool && !name.empty() && !tool->name.empty() && tool->name != name)
            reader.refuse(
                line, "name", name,
                "tool T" + std::to_string(t) + " is named '" + tool->name + "' on another edge");
        list.setEdge(static_cast<int>(t), edge, name);
    };
    auto section = [&](int process) { read[process]; };
    if (!readDataFrame(text, kToolFileFormat, reader, record, section) || reader.failed())
        return false;
    lists = std::move(read);
    return true;
}

}  // namespace mtc::core
