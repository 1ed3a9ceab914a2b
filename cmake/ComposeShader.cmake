# SPDX-License-Identifier: Apache-2.0
# Writes one GLSL file from an engine shader and the preludes the GL backend prepends to it at
# run time (src/engine/EnginePrograms.cpp), for glslc to compile to the Vulkan backend's SPIR-V.
#   cmake -DOUTPUT=x.comp -DDEFINES="MULTISAMPLE" -DPARTS="backend.glsl|light_view.glsl|body.comp"
#         -P ComposeShader.cmake
# The last part is the shader itself; its #version line is replaced by the composed one.
string(REPLACE "|" ";" PARTS "${PARTS}")
list(POP_BACK PARTS body)
set(text "#version 450\n")
foreach(define IN LISTS DEFINES)
  string(APPEND text "#define ${define}\n")
endforeach()
foreach(part IN LISTS PARTS)
  file(READ "${part}" source)
  string(APPEND text "${source}")
endforeach()
file(READ "${body}" source)
string(REGEX REPLACE "^#version[^\n]*\n" "" source "${source}")
string(APPEND text "\n#line 2\n${source}")
file(WRITE "${OUTPUT}.tmp" "${text}")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
