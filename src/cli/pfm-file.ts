/** Writing the rendered image's linear floats as a Portable Float Map (path-tracing spec §4). */
import { writeFile } from 'node:fs/promises';
import { describeFileError, InputError } from './cli-errors.ts';

/**
 * The PFM bytes of a width × height linear RGB image (3 floats per pixel, rows from the top,
 * as the renderer gives them): the header "PF", the size and −1 (little-endian), then the
 * rows from the bottom up, as the format has them (Debevec's HDRShop PFM).
 */
export function pfmBytes(rgb: Float32Array, width: number, height: number): Uint8Array {
  const header = new TextEncoder().encode(`PF\n${width} ${height}\n-1.0\n`);
  const bytes = new Uint8Array(header.length + width * height * 12);
  bytes.set(header);
  const floats = new DataView(bytes.buffer, header.length);
  for (let row = 0; row < height; row++) {
    const from = (height - 1 - row) * width * 3;
    for (let i = 0; i < width * 3; i++) floats.setFloat32((row * width * 3 + i) * 4, rgb[from + i]!, true);
  }
  return bytes;
}

export async function writePfm(file: string, rgb: Float32Array, width: number, height: number): Promise<void> {
  try {
    await writeFile(file, pfmBytes(rgb, width, height));
  } catch (error) {
    throw new InputError(`cannot write ${file}: ${describeFileError(error)}`);
  }
}
