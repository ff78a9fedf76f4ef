/** Saving the rendered image as a PNG download, with the exact rendered pixels. */

import { msg } from '@lit/localize';

const FILE_PREFIX = 'ray-tracer-quest';

/** Scene names are free text; file names get the part that is safe everywhere. */
const MAX_NAME_LENGTH = 40;

/**
 * The download's file name: `ray-tracer-quest-<scene>-<width>x<height>.png`, for example
 * `ray-tracer-quest-three-spheres-and-a-box-512x384.png`, so that renders of different scenes
 * and sizes do not overwrite each other in a Downloads folder. The scene name is reduced to
 * lower-case ASCII letters, digits and hyphens (accents dropped); it is left out when nothing
 * of it remains. A cancelled render's picture ends in `-partial`, so it is not taken for the finished one.
 */
export function pngFileName(sceneName: string | undefined, width: number, height: number, partial = false): string {
  const slug = (sceneName ?? '')
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '') // the accents NFKD split off their letters
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .slice(0, MAX_NAME_LENGTH)
    .replace(/^-+|-+$/g, '');
  return [FILE_PREFIX, slug, `${width}x${height}`, partial ? 'partial' : ''].filter((part) => part !== '').join('-') + '.png';
}

/**
 * Encodes the pixels as PNG (through an offscreen canvas at the image's own size, so they are
 * not the zoomed on-screen copy) and hands the file to the browser as a download.
 */
export async function savePng(pixels: ImageData, fileName: string): Promise<void> {
  const canvas = new OffscreenCanvas(pixels.width, pixels.height);
  const context = canvas.getContext('2d');
  if (!context) throw new Error(msg('this browser cannot draw the image for saving'));
  context.putImageData(pixels, 0, 0);
  const blob = await canvas.convertToBlob({ type: 'image/png' });
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.click();
  // Revoking at once can abort the download in some browsers; a minute is plenty to start it.
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}
