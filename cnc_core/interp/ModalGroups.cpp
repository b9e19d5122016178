#include "cnc_core/interp/ModalGroups.h"

#include <cctype>
#include <string>

namespace mtc::core {

namespace {

constexpr GCodeInfo classify(int number) {
    switch (number) {
        case 0:
        case 1:
        case 2:
        case 3:
            return {GKind::Modal, kGroupInterpolation};
        case 4:
            return {GKind::Dwell, 0};
        case 6:
        case 7:
            return {GKind::Modal, kGroupAcceleration};
        case 8:
        case 9:
            return {GKind::Modal, kGroupExactStop};
        case 15:
        case 16:
            return {GKind::Modal, kGroupRadiusDiameter};
        case 17:
        case 18:
        case 19:
        case 20:
            return {GKind::Modal, kGroupPlane};
        case 30:
        case 31:
        case 32:
            return {GKind::Modal, kGroupTransformation};
        case 40:
        case 41:
        case 42:
            return {GKind::Modal, kGroupToolPath};
        case 47:
        case 48:
            return {GKind::Modal, kGroupToolLength};
        case 53:
        case 54:
        case 55:
        case 56:
        case 57:
        case 58:
        case 59:
            return {GKind::Modal, kGroupZeroOffset};
        case 70:
        case 71:
            return {GKind::Modal, kGroupUnits};
        case 90:
        case 91:
            return {GKind::Modal, kGroupDimension};
        case 92:
            return {GKind::SpeedLimit, 0};
        case 74:  // homing
        case 75:  // driving against hard stop
        case 77:  // REPOS: back to the re-entry point (seed 000, 2.9 / 7)
            return {GKind::AxisFunction, 0};
        case 94:
        case 95:
            return {GKind::Modal, kGroupFeedType};
        case 96:
        case 97:
            return {GKind::Modal, kGroupSurfaceSpeed};
        case 25:
        case 26:  // adaptive feed control (seed 002)
            return {GKind::AdaptiveFeed, 0};
        // Named in the seeds, not executed by this simulator (yet):
        case 33:
        case 63:
        case 64:
        case 65:  // thread cutting, tapping
        case 50:
        case 51:
        case 52:  // programmable / incremental zero offsets
        case 72:
        case 73:
        case 76:
        case 78:
        case 79:
            return {GKind::Unsupported, 0};
        default:
            return {GKind::Unknown, 0};
    }
}

}  // namespace

const std::array<GCodeInfo, 100>& gCodeTable() {
    // Built at compile time: no initialisation guard on the decoder's path.
    static constexpr std::array<GCodeInfo, 100> table = [] {
        std::array<GCodeInfo, 100> t{};
        for (int g = 0; g < 100; ++g)
            t[static_cast<std::size_t>(g)] = classify(g);
        return t;
    }();
    return table;
}

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
