import { msg, str } from '@lit/localize';
import { errorMessage } from './render-job-controller.ts';

/** The scene view's raster (three.js) picture from the ray tracer's camera, at this size (drawn at once, maybe read back later). */
export type RasterSnapshot = (width: number, height: number) => ImageData | Promise<ImageData>;

/**
 * The raster picture's longest side. It is drawn and read back on the main thread in one go:
 * at 4096 × 4096 that blocked the page for 12.8 s on SwiftShader (the e2e run), against the
 * 50 ms a screen update may take. Larger images get a proportionally smaller picture, which
 * the comparison scales to the image's size.
 */
export const RASTER_MAX_SIDE = 1024;

/**
 * How long a render waits for its raster picture before its workers start: about 250 ms for a
 * 1024² picture on a software GPU, a few ms on a real one; a picture that never comes (a lost
 * GPU) does not hold the render back.
 */
export const RASTER_WAIT_MS = 1000;

/** A raster picture on its way, or why there is none. */
export type TakenPicture = { pixels: Promise<ImageData> } | { note: string };

/** Starts the raster picture of a `width` × `height` render now (the scene as it is), at most RASTER_MAX_SIDE a side. */
export function takeRasterPicture(snapshot: RasterSnapshot | undefined, width: number, height: number): TakenPicture {
  if (!snapshot) return { note: msg('Comparing with the raster view is not available here.') };
  const scale = Math.min(1, RASTER_MAX_SIDE / Math.max(width, height));
  try {
    return { pixels: Promise.resolve(snapshot(Math.max(1, Math.round(width * scale)), Math.max(1, Math.round(height * scale)))) };
  } catch (error) {
    return { note: notCaptured(error) };
  }
}

/**
 * Settles once the picture is read back (or has failed), or after RASTER_WAIT_MS. The render's
 * workers start then: the read-back ends in a synchronous round trip to the GPU process, which
 * on a software GPU with both cores tracing waited 100–250 ms behind the GPU process's frames,
 * the page frozen meanwhile (docs/benchmark-log.md, fifteenth round).
 */
export function readBackOrWait(pixels: Promise<ImageData>): Promise<unknown> {
  const waited = new Promise<void>((resolve) => setTimeout(resolve, RASTER_WAIT_MS));
  return Promise.race([pixels.catch(() => undefined), waited]);
}

/**
 * Draws the raster picture into `canvas` at its own size (CSS scales it on screen), unless the
 * render is no longer current. Through an ImageBitmap, which the browser makes off the main
 * thread: putImageData of a 2048 × 1536 picture blocked it for 50 ms. Resolves to why it could
 * not be shown, or ''.
 */
export async function paintRasterPicture(pixels: Promise<ImageData>, canvas: () => HTMLCanvasElement | undefined, isCurrent: () => boolean): Promise<string> {
  let image: ImageData;
  try {
    image = await pixels;
  } catch (error) {
    return notCaptured(error);
  }
  let bitmap: ImageBitmap;
  try {
    bitmap = await createImageBitmap(image);
  } catch (error) {
    return msg(str`The raster view could not be shown (${errorMessage(error)}).`);
  }
  const target = canvas();
  const context = target?.getContext('2d');
  if (isCurrent() && target && context) {
    target.width = bitmap.width;
    target.height = bitmap.height;
    context.drawImage(bitmap, 0, 0);
  }
  bitmap.close();
  return '';
}

function notCaptured(error: unknown): string {
  return msg(str`The raster view could not be captured (${errorMessage(error)}), so there is nothing to compare with.`);
}
