// libFuzzer target: arbitrary bytes as a command line of the tool, one
// argument per line ("polymass" before them), through parse_arguments.
//
// A command line is either parsed or refused with a UsageError saying why;
// --help's text is made as the tool prints it. Any other exception escaping,
// or a crash, is a finding.
#include <cstdint>
#include <string>
#include <vector>

#include "arguments.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace polymass_cli;
    std::vector<std::string> words{"polymass"};
    std::string word;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == '\n') {
            words.push_back(word);
            word.clear();
        } else {
            word.push_back(static_cast<char>(data[i]));
        }
    }
    if (!word.empty()) words.push_back(word);
    std::vector<const char*> argv;
    for (const std::string& w : words) argv.push_back(w.c_str());
    argv.push_back(nullptr);
    try {
        const Arguments arguments = parse_arguments(static_cast<int>(words.size()), argv.data());
        if (arguments.command == Command::kHelp) (void)help_text();
    } catch (const UsageError&) {
        // A clear refusal.
    }
    return 0;
}
