// The polymass tool's exit statuses, one per kind of outcome, so scripts can
// tell a bad command line from a file that cannot be read from a mesh that is
// not a valid solid. With several files the highest status wins.
#pragma once

namespace polymass_cli {

enum ExitCode : int {
    kExitOk = 0,           // every file read and every solid valid
    kExitInvalidMesh = 1,  // a file was read but is not a valid solid (open, inverted, ...)
    kExitUsage = 2,        // bad command line
    kExitUnreadable = 3,   // a file is missing, truncated, malformed or of unknown format
    kExitInternal = 4,     // out of memory, overflow, or a library bug
};

}  // namespace polymass_cli
