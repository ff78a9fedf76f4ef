/** Writing the rendered image as a PNG file (pngjs: pure JavaScript, no native build). */
import { constants } from 'node:fs';
import { access, stat, writeFile } from 'node:fs/promises';
import { dirname } from 'node:path';
import { PNG } from 'pngjs';
import { describeFileError, InputError } from './cli-errors.ts';

/** Fails before a long render rather than after it when `file` cannot be written. */
export async function checkWritable(file: string): Promise<void> {
  const existing = await stat(file).catch(() => null);
  if (existing?.isDirectory()) throw cannotWrite(file, 'it is a folder');
  try {
    await access(existing ? file : dirname(file), constants.W_OK);
  } catch (error) {
    throw cannotWrite(file, describeFileError(error));
  }
}

/** Writes 8-bit RGBA pixels as an RGB PNG (the alpha is always 255, so it is left out). */
export async function writePng(file: string, rgba: Uint8ClampedArray, width: number, height: number): Promise<void> {
  const png = new PNG({ width, height });
  png.data = Buffer.from(rgba.buffer, rgba.byteOffset, rgba.byteLength);
  try {
    await writeFile(file, PNG.sync.write(png, { colorType: 2 }));
  } catch (error) {
    throw cannotWrite(file, describeFileError(error));
  }
}

function cannotWrite(file: string, reason: string): InputError {
  return new InputError(`cannot write ${file}: ${reason}`);
}
