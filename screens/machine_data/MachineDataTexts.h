#pragma once

#include <QString>
#include <string>
#include <vector>

namespace mtc::screens {

/// The names the core gives its standard machine data pages
/// (cnc_core/machine_data/StandardPages.cpp: page titles, sub page titles,
/// element designations) in the panel's language, context "MachineData". A
/// name ending in a number ("T no. tool spindle 2") is translated by its
/// form ("T no. tool spindle %1"). The names of a user page come from the
/// machine configuration and are shown as written.
QString machineDataText(const std::string& name);

/// The forms of every name of the standard pages, as lupdate sees them
/// (gui.test_machine_data_screen checks each page against the catalogue).
const std::vector<const char*>& standardMachineDataTexts();

}  // namespace mtc::screens
