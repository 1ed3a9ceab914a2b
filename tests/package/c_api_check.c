// SPDX-License-Identifier: Apache-2.0
/* flarekit.h as a C compiler sees it, linked through pkg-config: the library's version, and an
 * engine refused before any GL work with its reason in fk_error(NULL), and a call on no engine
 * refused with FK_ERROR_INVALID; a flare set's preset from memory and the exported shaders. */
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
    /* The any-renderer part needs no GL: a preset from memory, its sprites, the shaders. */
    {
        static const char json[] = "{\"elements\": [{\"type\": \"glow\", \"size\": 0.1}]}";
        size_t size = 0;
        int width = 0, height = 0;
        fk_flare_set* set = fk_flare_set_create();
        if (set == NULL || fk_flare_set_load_preset_json(set, json, sizeof json - 1) != 0) return 5;
        if (fk_flare_set_prepare(set, 720) != 1) return 6;
        if (fk_flare_set_texture(set, 0, &width, &height, NULL) != 0 || width < 144) return 7;
        if (fk_flare_shader(FK_SHADER_HLSL, FK_SHADER_VERTEX, &size) == NULL || size < 100) return 8;
        fk_flare_set_destroy(set);
    }
    return 0;
}
