#include "cli/RestartReport.h"

#include "cli/CollisionReport.h"

#include <cstdio>
#include <string>

#include "cli/CliOutput.h"
#include "cli/MotionOutput.h"

namespace mtc::cli {

namespace {

std::string blockId(const core::ProgramPtr& program, std::uint32_t block) {
    return program && block < program->blocks.size() ? program->blockId(block) : std::string();
}

int lineOf(const core::ProgramPtr& program, std::uint32_t block) {
    return program && block < program->blocks.size() ? static_cast<int>(program->blocks[block].line)
                                                     : 0;
}

void writeTarget(JsonWriter& json, const RestartReport& r) {
    json.key("target");
    if (!r.accepted) return json.null();
    const core::ComputingProcess& c = r.sequence->computing();
    const core::ProgramPtr& program = c.route().targetProgram;
    const std::uint32_t block = c.selection().target.block;
    json.beginObject();
    json.key("program");
    json.value(program->number);
    json.key("block");
    json.value(blockId(program, block));
    json.key("line");
    json.value(lineOf(program, block));
    json.key("pass");
    json.value(static_cast<long long>(c.selection().runs));
    json.endObject();
}

void writeStart(JsonWriter& json, const RestartReport& r) {
    json.key("start");
    if (!r.accepted) return json.null();
    const core::RestartRoute& route = r.sequence->computing().route();
    json.beginObject();
    json.key("program");
    json.value(route.startProgram->number);
    json.key("block");
    json.value(blockId(route.startProgram, route.startBlock));
    json.key("line");
    json.value(lineOf(route.startProgram, route.startBlock));
    json.key("primary");
    json.value(route.primary);
    json.endObject();
}

void writeState(JsonWriter& json, const RestartReport& r, const StateSnapshot& s) {
    const std::vector<std::string> names = reportedAxisNames(*r.interpreter);
    writeStateJson(json,
                   {s.state, *r.process, r.interpreter->axes(), s.page61, names, s.positions});
}

void writeAux(JsonWriter& json, const RestartRecorder& recorder) {
    json.key("aux_output");
    json.beginArray();
    for (const RestartRecorder::Aux& aux : recorder.aux()) {
        json.beginObject();
        json.key("type");
        json.value(std::string(1, aux.output.type));
        json.key("value");
        json.value(aux.output.value);
        if (aux.output.type == 'S') {
            json.key("spindle");
            json.value(aux.output.spindle);
        }
        json.key("program");
        json.value(aux.output.where.program);
        json.key("block");
        json.value(aux.output.where.block);
        json.key("line");
        json.value(aux.output.where.line);
        json.key("phase");
        json.value(aux.phase);
        json.endObject();
    }
    json.endArray();
}

void writeSignals(JsonWriter& json, const core::SignalTable& signals) {
    json.key("signals");
    json.beginArray();
    long long step = 0;  // numbered from 1 in the order of change
    for (const core::SignalChange& change : signals.log()) {
        json.beginObject();
        json.key("name");
        json.value(change.name);
        json.key("value");
        json.value(change.value);
        json.key("step");
        json.value(++step);
        json.endObject();
    }
    json.endArray();
}

void writeMotions(JsonWriter& json, const char* key, const std::vector<core::Motion>& motions,
                  const std::vector<std::string>& names) {
    json.key(key);
    json.beginArray();
    MotionOutput out(MotionMode::Json, &json, nullptr);
    out.setAxisNames(names);
    for (const core::Motion& m : motions)
        out.motion(m);
    json.endArray();
}

}  // namespace

StateSnapshot takeSnapshot(const core::Interpreter& interpreter,
                           const core::MachineDataProvider& data, int process) {
    return {interpreter.state(), readPage61(data, process), programmedPositions(interpreter)};
}

void writeRestartJson(JsonWriter& json, const RestartReport& r) {
    json.beginObject();
    json.key("status");
    json.value(r.diagnostics.hasErrors() ? "error" : "ok");
    writeDiagnosticsJson(json, r.diagnostics);
    writeTarget(json, r);
    writeStart(json, r);
    json.key("blocks_interpreted");
    json.value(static_cast<long long>(
        r.accepted ? r.sequence->computing().progress().blocksInterpreted : 0));
    json.key("restart_phase");
    json.value(core::restartPhaseName(r.sequence->phase()));
    json.key("state");
    if (r.computed)
        writeState(json, r, *r.computed);
    else
        json.null();
    writeAux(json, *r.recorder);
    writeSignals(json, *r.signals);
    if (r.checkCollisions)
        writeCollisionsJson(json, r.collisions, reportedAxisNames(*r.interpreter));
    if (r.adjust) {
        const std::vector<std::string> names = reportedAxisNames(*r.interpreter);
        writeMotions(json, "adjust_motion", r.recorder->adjustMotion(), names);
        writeMotions(json, "repos_motion", r.recorder->reposMotion(), names);
        json.key("adjust_blocks");
        json.value(static_cast<long long>(r.sequence->sequenceBlocks()));
        json.key("final");
        if (r.final)
            writeState(json, r, *r.final);
        else
            json.null();
    }
    json.endObject();
    json.finish();
}

void printRestartText(const RestartReport& r) {
    printDiagnosticsText(stdout, r.diagnostics);
    if (r.accepted) {
        const core::ComputingProcess& c = r.sequence->computing();
        const core::RestartRoute& route = c.route();
        std::printf("target: P%d %s pass %u\n", route.targetProgram->number,
                    blockId(route.targetProgram, c.selection().target.block).c_str(),
                    c.selection().runs);
        std::printf("start: P%d %s%s\n", route.startProgram->number,
                    blockId(route.startProgram, route.startBlock).c_str(),
                    route.primary ? " (last primary block)" : "");
        std::printf("computing process: %s after %llu blocks\n",
                    core::computingStatusName(c.progress().status),
                    static_cast<unsigned long long>(c.progress().blocksInterpreted));
    }
    const std::vector<std::string> names = reportedAxisNames(*r.interpreter);
    if (r.computed)
        printStateText(stdout,
                       {r.computed->state, *r.process, r.interpreter->axes(), r.computed->page61,
                        names, r.computed->positions},
                       "target");
    for (const RestartRecorder::Aux& aux : r.recorder->aux()) {
        const core::AuxOutput& a = aux.output;
        const std::string spindle = a.type == 'S' ? std::to_string(a.spindle) + "=" : "";
        std::printf("aux P%d %s %c%s%g (%s)\n", a.where.program, a.where.block.c_str(), a.type,
                    spindle.c_str(), a.value, aux.phase.c_str());
    }
    int step = 0;
    for (const core::SignalChange& change : r.signals->log())
        std::printf("signal %d %s=%d\n", ++step, change.name.c_str(), change.value);
    if (r.checkCollisions) printCollisionsText(r.collisions, names);
    if (r.adjust)
        std::printf("ADJUST/REPOS: %zu + %zu motions, phase %s\n",
                    r.recorder->adjustMotion().size(), r.recorder->reposMotion().size(),
                    core::restartPhaseName(r.sequence->phase()));
    if (r.adjust && r.final)
        printStateText(stdout, {r.final->state, *r.process, r.interpreter->axes(), r.final->page61,
                                names, r.final->positions});
    std::printf("status: %s\n", r.diagnostics.hasErrors() ? "error" : "ok");
}

}  // namespace mtc::cli
