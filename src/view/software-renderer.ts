/**
 * Whether WebGL draws on the CPU here: SwiftShader, llvmpipe and the like, on a machine with
 * no usable GPU or one whose GPU the browser blocks (common on older school laptops). There
 * multisampling is what a frame of the 3D view costs most: on SwiftShader a slider step took
 * 222–355 ms to its rays on screen with it and 130–163 ms without (16 × 16 screen, same
 * machine, one after the other), so the view draws without it and stays responsive.
 */
export function drawsInSoftware(): boolean {
  const canvas = document.createElement('canvas');
  const gl = canvas.getContext('webgl2') ?? canvas.getContext('webgl');
  if (!gl) return false;
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return isSoftwareRenderer(name);
}

/** Whether a WebGL renderer's name is one of the CPU rasterizers. */
export function isSoftwareRenderer(name: string): boolean {
  return /swiftshader|llvmpipe|softpipe|software rasterizer|microsoft basic render/i.test(name);
}
