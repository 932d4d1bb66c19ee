// The instruction sets the hot loops are built for, chosen at run time: the
// shipped library is built for the baseline, and wider code only ever runs on
// a processor that has it. On x86-64 all three, elsewhere the baseline only.
// Every one gives the same bits (lanes.hpp).
#pragma once

namespace polymass::core {

// avx2 is AVX2 with FMA, which every processor with AVX2 has had (Haswell,
// Excavator and later): the integration's kernel fuses its move into the
// frame (docs/integrals.md, section 5).
enum class InstructionSet { baseline, avx2, avx512 };

// Whether this processor (and its operating system) runs code built for `set`.
bool runs_instruction_set(InstructionSet set);
// The widest set it runs, found once.
InstructionSet widest_instruction_set();

}  // namespace polymass::core
