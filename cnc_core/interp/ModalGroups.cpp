#include "cnc_core/interp/ModalGroups.h"

#include <cctype>
#include <string>

namespace mtc::core {

GGroupValues defaultGGroups(const ProcessConfig& config) {
    GGroupValues g;
    g.fill(-1);
    g[kGroupInterpolation] = 0;
    const int plane = config.defaultPlane();
    g[kGroupPlane] = static_cast<std::int16_t>(plane == 18 || plane == 19 ? plane : 17);
    g[kGroupToolPath] = 40;
    g[kGroupZeroOffset] = 53;
    g[kGroupFeedType] = 94;
    g[kGroupDimension] = 90;
    auto it = config.parameters.find("B015");
    std::string b015 = it == config.parameters.end() ? "" : it->second;
    for (char& ch : b015)
        ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    g[kGroupRadiusDiameter] = (b015 == "diameter" || b015 == "16" || b015 == "g16") ? 16 : 15;
    g[kGroupUnits] = 71;
    g[kGroupSurfaceSpeed] = 97;
    g[kGroupAcceleration] = 6;
    g[kGroupExactStop] = 8;
    g[kGroupToolLength] = 47;
    g[kGroupTransformation] = 30;
    return g;
}

const std::array<int, 13>& usedGGroups() {
    static constexpr std::array<int, 13> kGroups = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 17};
    return kGroups;
}

GGroupName gGroupName(int group) {
    switch (group) {
        case kGroupInterpolation:
            return {"interpolation", "interpolation"};
        case kGroupPlane:
            return {"plane", "plane"};
        case kGroupToolPath:
            return {"radius comp.", "tool path compensation"};
        case kGroupZeroOffset:
            return {"zero offset", "zero offset"};
        case kGroupFeedType:
            return {"feed type", "feed type"};
        case kGroupDimension:
            return {"dimensions", "dimension"};
        case kGroupRadiusDiameter:
            return {"radius/diameter", "radius / diameter"};
        case kGroupUnits:
            return {"units", "units"};
        case kGroupSurfaceSpeed:
            return {"spindle speed", "surface speed"};
        case kGroupAcceleration:
            return {"acceleration", "G6 / G7"};
        case kGroupExactStop:
            return {"exact stop", "G8 / G9"};
        case kGroupToolLength:
            return {"length comp.", "tool length compensation"};
        case kGroupTransformation:
            return {"transformation", "transformation"};
        default:
            return {};
    }
}

}  // namespace mtc::core
