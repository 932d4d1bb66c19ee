// String streams that throw std::bad_alloc when memory runs out, for every
// text the tool builds or splits with a stream. A standard stream catches
// what its buffer or a conversion throws and only sets badbit: output written
// after would be dropped and the text printed cut short, as if whole; input
// would end early, as if the text did ("wants 3 numbers"). With badbit among
// its exceptions, the stream throws the std::bad_alloc again.
#pragma once

#include <ios>
#include <sstream>
#include <string>

namespace polymass_cli {

class OutputText : public std::ostringstream {
public:
    OutputText() { exceptions(std::ios::badbit); }
};

class InputText : public std::istringstream {
public:
    explicit InputText(const std::string& text) : std::istringstream(text) {
        exceptions(std::ios::badbit);
    }
};

}  // namespace polymass_cli
