#include "xml_memory.hpp"

#include <new>
#include <pugixml.hpp>

namespace polymass_cli {
namespace {

void* allocate(size_t size) { return ::operator new(size); }
void deallocate(void* memory) { ::operator delete(memory); }

}  // namespace

void pugixml_allocates_with_new() {
    static const bool set = [] {
        pugi::set_memory_management_functions(allocate, deallocate);
        return true;
    }();
    (void)set;
}

}  // namespace polymass_cli
