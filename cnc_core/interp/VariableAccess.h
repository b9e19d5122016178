#pragma once

namespace mtc::core {

/// Access to the variables of the other processes of the cell (@p:n with p
/// not the running process). The cell that owns several interpreters
/// implements it; without one, @p:n of another process is a diagnostic.
class VariableAccess {
  public:
    virtual ~VariableAccess() = default;
    /// Reads @process:index; false when the process or variable does not exist.
    virtual bool read(int process, int index, double& value) const = 0;
    /// Writes @process:index; false (nothing written) when it does not exist.
    virtual bool write(int process, int index, double value) = 0;
};

}  // namespace mtc::core
