#include "instruction_sets.hpp"

#include <initializer_list>

namespace polymass::core {

bool runs_instruction_set(InstructionSet set) {
#if defined(__x86_64__)
    switch (set) {
        case InstructionSet::avx512:
            return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                   __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
        case InstructionSet::avx2:
            return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
        case InstructionSet::baseline:
            return true;
    }
    return false;
#else
    return set == InstructionSet::baseline;
#endif
}

InstructionSet widest_instruction_set() {
    static const InstructionSet widest = [] {
        for (InstructionSet set : {InstructionSet::avx512, InstructionSet::avx2})
            if (runs_instruction_set(set)) return set;
        return InstructionSet::baseline;
    }();
    return widest;
}

}  // namespace polymass::core
