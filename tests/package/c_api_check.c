// SPDX-License-Identifier: Apache-2.0
/* flarekit.h as a C compiler sees it, linked through pkg-config: the library's version, and an
 * engine refused before any GL work with its reason in fk_error(NULL), and a call on no engine
 * refused with FK_ERROR_INVALID. */
#include <flarekit/flarekit.h>
#include <stdio.h>
#include <string.h>

int main(void) {
    fk_engine* engine;
    if (fk_version() != FK_VERSION_MAJOR * 10000 + FK_VERSION_MINOR * 100) return 1;
    engine = fk_engine_create(0);
    if (engine != NULL) return 2;
    if (strstr(fk_error(NULL), "max_lights: expected 1..") == NULL) return 3;
    printf("%s\n", fk_error(NULL));
    /* A call on no engine: the invalid-argument code, the C side of the library's InvalidInput. */
    if (fk_engine_occlusion(NULL, NULL, NULL, 0) != FK_ERROR_INVALID) return 4;
    return 0;
}
