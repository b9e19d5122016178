#include "cnc_core/machine_data/MachineDataStore.h"

#include <cmath>

#include "cnc_core/machine_data/StandardPages.h"

namespace mtc::core {
namespace {

std::vector<double> defaultsOf(const MachineDataPage& page) {
    std::vector<double> values;
    for (std::size_t sub = 0; sub < page.subs().size(); ++sub)
        for (const MachineDataElement& e : page.elements)
            values.push_back(e.defaultValue);
    return values;
}

}  // namespace

MachineDataStore::MachineDataStore(const MachineConfig& config)
    : cellName_(config.name),
      password_(config.machineDataPassword.empty() ? kDefaultMachineDataPassword
                                                   : config.machineDataPassword) {
    for (const ProcessConfig& process : config.processes) {
        processOrder_.push_back(process.index);
        ProcessPages& pages = processes_[process.index];
        std::vector<MachineDataPage> definitions = {adaptiveFeedPage(), restartPage(),
                                                    functionBufferPage()};
        for (const UserDataPage& user : process.userPages)
            definitions.push_back(userPage(user));
        for (MachineDataPage& definition : definitions) {
            const int number = definition.number;
            std::vector<double> values = defaultsOf(definition);
            pages[number] = PageData{std::move(definition), std::move(values)};
        }
    }
}

template <class Processes, class Page>
MachineDataStatus MachineDataStore::locateIn(Processes& processes, const MachineDataAddress& a,
                                             Page*& page, std::size_t& index) {
    auto process = processes.find(a.process);
    if (process == processes.end()) {
        for (const auto& [number, pages] : processes)
            if (pages.count(a.page)) return MachineDataStatus::UnknownProcess;
        return MachineDataStatus::UnknownPage;
    }
    auto found = process->second.find(a.page);
    if (found == process->second.end()) return MachineDataStatus::UnknownPage;
    const MachineDataPage& definition = found->second.definition;
    const int slot = definition.subSlot(a.sub);
    const int element = definition.elementIndex(a.element);
    if (slot < 0 || element < 0) return MachineDataStatus::UnknownElement;
    page = &found->second;
    index = static_cast<std::size_t>(slot) * definition.elements.size() +
            static_cast<std::size_t>(element);
    return MachineDataStatus::Ok;
}

MachineDataStatus MachineDataStore::read(const MachineDataAddress& address, double& value) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const PageData* page = nullptr;
    std::size_t index = 0;
    const MachineDataStatus status = locateIn(processes_, address, page, index);
    if (status == MachineDataStatus::Ok) value = page->values[index];
    return status;
}

MachineDataStatus MachineDataStore::fits(const MachineDataElement& element, double value,
                                         double& normalized) {
    if (!std::isfinite(value)) return MachineDataStatus::OutOfRange;
    const std::optional<double> stored = normalizeMachineDataValue(element.type, value);
    if (!stored) return MachineDataStatus::WrongType;
    if (*stored < element.minimum || *stored > element.maximum)
        return MachineDataStatus::OutOfRange;
    normalized = *stored;
    return MachineDataStatus::Ok;
}

MachineDataStatus MachineDataStore::validate(const MachineDataAddress& address, double value,
                                             MachineDataWriter writer, std::string_view password,
                                             bool ignoreProtection, double& normalized) const {
    const PageData* page = nullptr;
    std::size_t index = 0;
    const MachineDataStatus status = locateIn(processes_, address, page, index);
    if (status != MachineDataStatus::Ok) return status;
    const MachineDataElement& element =
        page->definition.elements[index % page->definition.elements.size()];
    if (!ignoreProtection) {
        if (element.protectedFor(writer)) return MachineDataStatus::WriteProtected;
        if (writer == MachineDataWriter::Gui && element.password) {
            if (password.empty()) return MachineDataStatus::PasswordRequired;
            if (password != password_) return MachineDataStatus::WrongPassword;
        }
    }
    return fits(element, value, normalized);
}

MachineDataStatus MachineDataStore::check(const MachineDataAddress& address, double value,
                                          MachineDataWriter writer) const {
    return check(address, value, writer, {});
}

MachineDataStatus MachineDataStore::check(const MachineDataAddress& address, double value,
                                          MachineDataWriter writer,
                                          std::string_view password) const {
    std::lock_guard<std::mutex> lock(mutex_);
    double normalized = 0.0;
    return validate(address, value, writer, password, false, normalized);
}

MachineDataStatus MachineDataStore::store(const MachineDataAddress& address, double value,
                                          MachineDataWriter writer, std::string_view password,
                                          bool ignoreProtection) {
    std::lock_guard<std::mutex> lock(mutex_);
    double normalized = 0.0;
    const MachineDataStatus status =
        validate(address, value, writer, password, ignoreProtection, normalized);
    if (status != MachineDataStatus::Ok) return status;
    // -0 is kept as 0: otherwise a -0 over a 1 stays -0 while a -0 over the
    // default 0 does not, and the file text depends on the order of writes
    // (fuzz finding machine_data 32bf168).
    if (normalized == 0.0) normalized = 0.0;
    PageData* page = nullptr;
    std::size_t index = 0;
    locateIn(processes_, address, page, index);
    double& slot = page->values[index];
    if (slot != normalized) {
        slot = normalized;
        revision_.fetch_add(1, std::memory_order_acq_rel);
    }
    return MachineDataStatus::Ok;
}

MachineDataStatus MachineDataStore::write(const MachineDataAddress& address, double value,
                                          MachineDataWriter writer) {
    return store(address, value, writer, {}, false);
}

MachineDataStatus MachineDataStore::write(const MachineDataAddress& address, double value,
                                          MachineDataWriter writer, std::string_view password) {
    return store(address, value, writer, password, false);
}

MachineDataStatus MachineDataStore::update(const MachineDataAddress& address, double value) {
    return store(address, value, MachineDataWriter::Nc, {}, true);
}

void MachineDataStore::resetToDefaults() {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto& [process, pages] : processes_)
        for (auto& [number, page] : pages)
            page.values = defaultsOf(page.definition);
    revision_.fetch_add(1, std::memory_order_acq_rel);
}

std::vector<MachineDataStore::Entry> MachineDataStore::restore(const std::vector<Entry>& entries) {
    std::vector<Entry> rejected;
    for (const Entry& entry : entries)
        if (update(entry.address, entry.value) != MachineDataStatus::Ok) rejected.push_back(entry);
    return rejected;
}

bool MachineDataStore::passwordMatches(std::string_view password) const {
    return password == password_;
}

std::vector<int> MachineDataStore::processes() const {
    return processOrder_;
}

std::vector<int> MachineDataStore::pageNumbers(int process) const {
    std::vector<int> numbers;
    auto found = processes_.find(process);
    if (found == processes_.end()) return numbers;
    for (const auto& [number, page] : found->second)
        numbers.push_back(number);
    return numbers;
}

const MachineDataPage* MachineDataStore::page(int process, int number) const {
    auto found = processes_.find(process);
    if (found == processes_.end()) return nullptr;
    auto page = found->second.find(number);
    return page == found->second.end() ? nullptr : &page->second.definition;
}

std::vector<MachineDataStore::Entry> MachineDataStore::entries() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<Entry> result;
    for (const auto& [process, pages] : processes_)
        for (const auto& [number, page] : pages) {
            const std::vector<int> subs = page.definition.subs();
            const std::size_t count = page.definition.elements.size();
            for (std::size_t s = 0; s < subs.size(); ++s)
                for (std::size_t e = 0; e < count; ++e)
                    result.push_back(
                        {{number, process, subs[s], page.definition.elements[e].number},
                         page.values[s * count + e]});
        }
    return result;
}

}  // namespace mtc::core
