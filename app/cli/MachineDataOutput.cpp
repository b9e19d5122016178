#include "cli/MachineDataOutput.h"

#include <cstdio>

#include "cli/CliOutput.h"
#include "cli/JsonWriter.h"

namespace mtc::cli {
namespace {

using core::MachineDataElement;
using core::MachineDataPage;
using core::MachineDataStore;

std::string protectionText(const MachineDataElement& e) {
    std::string text;
    if (e.protectedNc) text += "NC ";
    if (e.protectedSps) text += "SPS ";
    if (e.protectedGui) text += "GUI ";
    if (e.password) text += "password";
    if (text.empty()) return "-";
    if (text.back() == ' ') text.pop_back();
    return text;
}

double valueAt(const MachineDataStore& store, int page, int process, int sub, int element) {
    double value = 0.0;
    store.read({page, process, sub, element}, value);
    return value;
}

void printFooter(const MachineDataReport& report) {
    std::printf("data file: %s\n",
                report.dataFile.empty() ? "(none: nothing is kept)" : report.dataFile.c_str());
    printDiagnosticsText(stderr, report.diagnostics);
}

void writeElementJson(JsonWriter& json, const MachineDataElement& e, double value) {
    json.beginObject();
    json.field("number", e.number);
    json.field("title", e.designation);
    json.field("value", value);
    json.field("unit", e.unit);
    json.field("type", core::machineDataTypeName(e.type));
    json.field("min", e.minimum);
    json.field("max", e.maximum);
    json.field("default", e.defaultValue);
    json.key("write_protected");
    json.beginObject();
    json.field("nc", e.protectedNc);
    json.field("sps", e.protectedSps);
    json.field("gui", e.protectedGui);
    json.endObject();
    json.field("password", e.password);
    json.endObject();
}

void writeHead(JsonWriter& json, const char* status, const MachineDataReport& report) {
    beginStatusDocument(json, status);
    json.field("process", report.process);
    json.key("data_file");
    if (report.dataFile.empty())
        json.null();
    else
        json.value(report.dataFile);
}

}  // namespace

void printPageText(const MachineDataStore& store, const MachineDataPage& page,
                   const MachineDataReport& report, int onlySub) {
    std::printf("page %d \"%s\", process %d (%s)\n", page.number, page.title.c_str(),
                report.process, report.processName.c_str());
    for (int sub : page.subs()) {
        if (onlySub >= 0 && sub != onlySub) continue;
        if (sub != 0) std::printf("sub %d: %s\n", sub, page.subTitles[sub - 1].c_str());
        std::printf("%-4s %-32s %12s %-5s %-5s %s\n", "Nr.", "Title", "Value", "Unit", "Type",
                    "Protection");
        for (const MachineDataElement& e : page.elements) {
            const double value = valueAt(store, page.number, report.process, sub, e.number);
            std::printf("%03d  %-32s %12s %-5s %-5s %s\n", e.number, e.designation.c_str(),
                        core::formatMachineDataValue(e.type, value).c_str(), e.unit.c_str(),
                        core::machineDataTypeName(e.type), protectionText(e).c_str());
        }
    }
    printFooter(report);
}

void printPageJson(const MachineDataStore& store, const MachineDataPage& page,
                   const MachineDataReport& report, int onlySub) {
    JsonWriter json(stdout);
    writeHead(json, "ok", report);
    json.field("page", page.number);
    json.field("title", page.title);
    json.key("subs");
    json.beginArray();
    for (int sub : page.subs()) {
        if (onlySub >= 0 && sub != onlySub) continue;
        json.beginObject();
        json.field("sub", sub);
        json.field("title", sub == 0 ? std::string() : page.subTitles[sub - 1]);
        json.key("elements");
        json.beginArray();
        for (const MachineDataElement& e : page.elements)
            writeElementJson(json, e, valueAt(store, page.number, report.process, sub, e.number));
        json.endArray();
        json.endObject();
    }
    json.endArray();
    endDocumentWithDiagnostics(json, report.diagnostics);
}

void printPageList(const MachineDataStore& store, const MachineDataReport& report, bool json) {
    const std::vector<int> numbers = store.pageNumbers(report.process);
    if (!json) {
        std::printf("machine data pages of process %d (%s):\n", report.process,
                    report.processName.c_str());
        for (int number : numbers)
            std::printf("%4d  %s\n", number, store.page(report.process, number)->title.c_str());
        printFooter(report);
        return;
    }
    JsonWriter out(stdout);
    writeHead(out, "ok", report);
    out.key("pages");
    out.beginArray();
    for (int number : numbers) {
        out.beginObject();
        out.field("page", number);
        out.field("title", store.page(report.process, number)->title);
        out.endObject();
    }
    out.endArray();
    endDocumentWithDiagnostics(out, report.diagnostics);
}

void printSetResult(const core::MachineDataAddress& a, const MachineDataElement& e, double before,
                    double after, const MachineDataReport& report, bool json) {
    if (!json) {
        const std::string sub = a.sub ? " sub " + std::to_string(a.sub) : "";
        std::printf("page %d process %d%s element %03d %s: %s -> %s %s\n", a.page, a.process,
                    sub.c_str(), a.element, e.designation.c_str(),
                    core::formatMachineDataValue(e.type, before).c_str(),
                    core::formatMachineDataValue(e.type, after).c_str(), e.unit.c_str());
        printFooter(report);
        return;
    }
    JsonWriter out(stdout);
    writeHead(out, "ok", report);
    out.field("page", a.page);
    out.field("sub", a.sub);
    out.field("element", a.element);
    out.field("title", e.designation);
    out.field("old", before);
    out.field("value", after);
    out.field("saved", !report.dataFile.empty());
    endDocumentWithDiagnostics(out, report.diagnostics);
}

void printRefusal(const MachineDataReport& report, bool json) {
    if (!json) {
        printRefusedDiagnostics(report.diagnostics);
        return;
    }
    JsonWriter out(stdout);
    writeHead(out, "error", report);
    endDocumentWithDiagnostics(out, report.diagnostics);
}

}  // namespace mtc::cli
