// SPDX-License-Identifier: Apache-2.0
// FK_CHECK: contract checks inside the library. A failed check is a flarekit bug, never bad
// user input (that is returned as an Error): it prints the condition with the values and aborts.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <sstream>

#define FK_CHECK(cond, values)                                                                    \
    do {                                                                                          \
        if (!(cond)) {                                                                            \
            std::ostringstream fk_check_os;                                                       \
            fk_check_os << values;                                                                \
            std::fprintf(stderr, "flarekit: internal check failed at %s:%d: %s (%s)\n", __FILE__, \
                         __LINE__, #cond, fk_check_os.str().c_str());                             \
            std::abort();                                                                         \
        }                                                                                         \
    } while (0)
