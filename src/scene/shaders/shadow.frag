#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Shadow pass: depth only.
void main() {}
