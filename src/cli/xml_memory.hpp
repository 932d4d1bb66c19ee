// How pugixml allocates, for every XML document of the tool: the audit's
// robot descriptions, the --urdf/--sdf/--mjcf output, Collada's <asset>.
#pragma once

namespace polymass_cli {

// pugixml allocates with malloc and, when that fails, goes on quietly: a
// node it could not add is an empty one (an <inertial> missing from the
// output), a parse ends as "Could not allocate memory" (a description called
// malformed). With operator new instead, a failure is std::bad_alloc - the
// tool's out-of-memory ending, or in a reader's child the failed allocation
// its parent reports - and the out-of-memory test reaches pugixml's
// allocations under AddressSanitizer too. Call before making a document;
// the first call sets it for the process, the others do nothing.
void pugixml_allocates_with_new();

}  // namespace polymass_cli
