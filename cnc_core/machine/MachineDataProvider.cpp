#include "cnc_core/machine/MachineDataProvider.h"

namespace mtc::core {

const char* machineDataStatusCode(MachineDataStatus status) {
    switch (status) {
        case MachineDataStatus::Ok:
            return "";
        case MachineDataStatus::UnknownPage:
            return "MTD_UNKNOWN_PAGE";
        case MachineDataStatus::UnknownProcess:
            return "MTD_UNKNOWN_PROCESS";
        case MachineDataStatus::UnknownElement:
            return "MTD_UNKNOWN_ELEMENT";
        case MachineDataStatus::OutOfRange:
            return "MTD_OUT_OF_RANGE";
        case MachineDataStatus::WriteProtected:
            return "MTD_WRITE_PROTECTED";
        case MachineDataStatus::WrongType:
            return "MTD_WRONG_TYPE";
        case MachineDataStatus::PasswordRequired:
            return "MTD_PASSWORD_REQUIRED";
        case MachineDataStatus::WrongPassword:
            return "MTD_WRONG_PASSWORD";
    }
    return "MTD_ERROR";
}

const char* machineDataStatusText(MachineDataStatus status) {
    switch (status) {
        case MachineDataStatus::Ok:
            return "ok";
        case MachineDataStatus::UnknownPage:
            return "no such machine data page";
        case MachineDataStatus::UnknownProcess:
            return "the page does not exist for that process";
        case MachineDataStatus::UnknownElement:
            return "no such element on the page";
        case MachineDataStatus::OutOfRange:
            return "value outside the element's value range";
        case MachineDataStatus::WriteProtected:
            return "the element is write-protected";
        case MachineDataStatus::WrongType:
            return "the element takes whole numbers only";
        case MachineDataStatus::PasswordRequired:
            return "the element is password-protected: a password is required";
        case MachineDataStatus::WrongPassword:
            return "wrong password";
    }
    return "machine data error";
}

}  // namespace mtc::core
