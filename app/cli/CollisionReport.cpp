#include "cli/CollisionReport.h"

#include <cstdio>

namespace mtc::cli {

namespace {

const char* phaseOf(const core::removal::ReentryCollision& c) {
    return c.repos ? "repos" : "adjust";
}

/// "feed" for a move that would cut, "rapid" for a G0 that touches.
const char* motionOf(const core::removal::ReentryCollision& c) {
    return c.rapid ? "rapid" : "feed";
}

void writePosition(JsonWriter& json, const core::removal::ReentryCollision& c,
                   const std::vector<std::string>& names) {
    json.key("position");
    json.beginObject();
    for (std::size_t axis = 0; axis < names.size() && axis < c.position.size(); ++axis) {
        if (names[axis].empty()) continue;
        json.key(names[axis]);
        json.value(c.position[axis]);
    }
    json.endObject();
}

}  // namespace

void writeCollisionsJson(JsonWriter& json, const std::optional<core::removal::ReentryCheck>& check,
                         const std::vector<std::string>& names) {
    json.key("collision_check");
    if (!check) {
        json.null();
    } else {
        json.beginObject();
        json.field("checked", check->checked);
        json.key("moves");
        json.value(static_cast<long long>(check->moves));
        json.key("resolution");
        json.value(check->resolution);
        json.key("tolerance");
        json.value(check->tolerance);
        json.key("removed_volume");
        json.value(check->removedVolume);
        json.endObject();
    }
    json.key("collisions");
    json.beginArray();
    if (check)
        for (const core::removal::ReentryCollision& c : check->collisions) {
            json.beginObject();
            json.field("block", c.where.block);
            json.key("program");
            json.value(c.where.program);
            json.key("line");
            json.value(c.where.line);
            json.field("phase", phaseOf(c));
            json.field("motion", motionOf(c));
            writePosition(json, c, names);
            json.endObject();
        }
    json.endArray();
}

void printCollisionsText(const std::optional<core::removal::ReentryCheck>& check,
                         const std::vector<std::string>& names) {
    if (!check) {
        std::printf("collision check: not done (the restart did not reach its target)\n");
        return;
    }
    if (!check->checked) {
        std::printf("collision check: not done (see the diagnostics)\n");
        return;
    }
    for (const core::removal::ReentryCollision& c : check->collisions) {
        std::string line = std::string("collision ") + phaseOf(c) + " P" +
                           std::to_string(c.where.program) + ' ' +
                           (c.where.block.empty() ? "-" : c.where.block) + " L" +
                           std::to_string(c.where.line) + ' ' + motionOf(c);
        for (std::size_t axis = 0; axis < names.size() && axis < c.position.size(); ++axis) {
            if (names[axis].empty()) continue;
            line += ' ' + names[axis] + '=';
            JsonWriter::appendNumber(line, c.position[axis]);
        }
        std::printf("%s\n", line.c_str());
    }
    std::printf("collision check: %zu of %zu ADJUST/REPOS moves collide (tolerance %g mm)\n",
                check->collisions.size(), check->moves, check->tolerance);
}

}  // namespace mtc::cli
