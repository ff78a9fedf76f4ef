import { describe, expect, it } from 'vitest';
import { isSoftwareRenderer } from '../../src/view/software-renderer.ts';

describe('telling a CPU rasterizer from a GPU by its WebGL name', () => {
  it('knows the software renderers browsers fall back to', () => {
    expect(isSoftwareRenderer('ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)')).toBe(true);
    expect(isSoftwareRenderer('llvmpipe (LLVM 15.0.6, 256 bits)')).toBe(true);
    expect(isSoftwareRenderer('ANGLE (Microsoft, Microsoft Basic Render Driver Direct3D11 vs_5_0 ps_5_0)')).toBe(true);
  });

  it('leaves real GPUs alone', () => {
    expect(isSoftwareRenderer('ANGLE (Intel, Intel(R) UHD Graphics 620 Direct3D11 vs_5_0 ps_5_0, D3D11)')).toBe(false);
    expect(isSoftwareRenderer('Mali-G52')).toBe(false);
    expect(isSoftwareRenderer('Apple M1')).toBe(false);
  });
});
