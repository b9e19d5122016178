#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/MachineDataProvider.h"
#include "cnc_core/machine_data/MachineDataPage.h"

namespace mtc::core {

/// Password of password-protected elements when the configuration names
/// none (`[cell] md_password`); docs/decisions/machine-data.md MD-004.
constexpr const char* kDefaultMachineDataPassword = "MTC200";

/// The machine data of one cell: pages 30, 60 and 61 for every process and
/// the user pages of each process from the configuration, with per process
/// one value per element (and sub). Writes follow the element definitions:
/// write protection per writer (NC, SPS, GUI), the password for the
/// operator, whole numbers for BOOL/SINT/UINT/INT, rounding to the decimals
/// of AMPL/PERC, the value range. Thread-safe; never throws.
class MachineDataStore : public MachineDataProvider {
  public:
    /// One value of the store, for persistence and listings.
    struct Entry {
        MachineDataAddress address;
        double value = 0.0;
    };

    /// Every page starts at its default values.
    explicit MachineDataStore(const MachineConfig& config);

    /// Reads one element; `value` is untouched unless Ok.
    MachineDataStatus read(const MachineDataAddress& address, double& value) const override;
    /// What write() would answer (without a password), without writing.
    MachineDataStatus check(const MachineDataAddress& address, double value,
                            MachineDataWriter writer) const override;
    /// Writes one element without a password: an operator write of a
    /// password-protected element answers PasswordRequired. Nothing changes unless Ok.
    MachineDataStatus write(const MachineDataAddress& address, double value,
                            MachineDataWriter writer) override;

    /// check() with the operator's password (ignored for NC and SPS).
    MachineDataStatus check(const MachineDataAddress& address, double value,
                            MachineDataWriter writer, std::string_view password) const;
    /// write() with the operator's password (ignored for NC and SPS).
    MachineDataStatus write(const MachineDataAddress& address, double value,
                            MachineDataWriter writer, std::string_view password);
    /// The NC's own update of an element (status values of page 30, the
    /// computing process): write protection does not apply, type and range do.
    MachineDataStatus update(const MachineDataAddress& address, double value);
    /// Sets every element of every page back to its default.
    void resetToDefaults();
    /// Puts stored values back (persistence): each entry is checked like
    /// update(); the entries that do not fit are returned, the rest is set.
    std::vector<Entry> restore(const std::vector<Entry>& entries);

    /// True when `password` is the machine data password of the cell.
    bool passwordMatches(std::string_view password) const;
    /// Process numbers of the cell in configuration order.
    std::vector<int> processes() const;
    /// Page numbers of a process, ascending (empty for an unknown process).
    std::vector<int> pageNumbers(int process) const;
    /// The page definition, or nullptr. Valid as long as the store lives.
    const MachineDataPage* page(int process, int number) const;
    /// Every value of every page, ordered by process, page, sub, element.
    std::vector<Entry> entries() const;
    /// Increases with every change of a value (screens poll it).
    std::uint64_t revision() const { return revision_.load(std::memory_order_acquire); }
    /// Name of the cell (persistence files record it).
    const std::string& cellName() const { return cellName_; }

  private:
    struct PageData {
        MachineDataPage definition;
        std::vector<double> values;  ///< sub slot * elements + element index
    };
    using ProcessPages = std::map<int, PageData>;

    /// The page data (const or not) and value index of `address`, or a status.
    template <class Processes, class Page>
    static MachineDataStatus locateIn(Processes& processes, const MachineDataAddress& address,
                                      Page*& page, std::size_t& index);
    /// Type, range and protection of a write; `normalized` gets the stored value.
    MachineDataStatus validate(const MachineDataAddress& address, double value,
                               MachineDataWriter writer, std::string_view password,
                               bool ignoreProtection, double& normalized) const;
    MachineDataStatus store(const MachineDataAddress& address, double value,
                            MachineDataWriter writer, std::string_view password,
                            bool ignoreProtection);
    static MachineDataStatus fits(const MachineDataElement& element, double value,
                                  double& normalized);

    std::string cellName_;
    std::string password_;
    std::vector<int> processOrder_;
    std::map<int, ProcessPages> processes_;
    mutable std::mutex mutex_;
    std::atomic<std::uint64_t> revision_{0};
};

}  // namespace mtc::core
