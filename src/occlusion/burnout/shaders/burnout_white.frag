#version 450 core
// Burnout chain, pass 1 over the 14x14 grid of cells laid on the sun's square: the white
// rectangle, drawn without depth test. Each cell also takes the frame's depth at its centre
// (the PSP draws straight over its frame buffer; here the frame's depth is copied into the
// grid's own depth buffer) and, in G, its weight: the share of the cell inside the disc x
// cos^3, so the chain measures the disc, not the square. Off-screen cells weigh 0.
uniform vec2 regionOrigin;  // GL pixels, bottom-left of the square
uniform float cellSize;     // pixels per cell
layout(binding = 0) uniform sampler2D sceneDepth;
out vec4 fragColor;
void main() {
    vec2 cell = floor(gl_FragCoord.xy);
    vec2 corner = regionOrigin + cell * cellSize;
    vec2 centre = corner + 0.5 * cellSize;
    bool onScreen = all(greaterThanEqual(centre, vec2(0.0))) && all(lessThan(centre, frameSize));
    int inside = 0;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            if (inSunDisc(rayThrough(corner + (vec2(i, j) + 0.5) / 4.0 * cellSize))) ++inside;
    float cosTheta = dot(rayThrough(centre), camForward);
    float weight = onScreen ? float(inside) / 16.0 * cosTheta * cosTheta * cosTheta : 0.0;
    gl_FragDepth = onScreen ? texelFetch(sceneDepth, ivec2(centre), 0).r : 0.0;
    fragColor = vec4(1.0, weight, 0.0, 1.0);
}
