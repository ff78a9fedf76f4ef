import type { LabServices } from '../../app/lab-services.ts';
import type { Scene } from '../../scene/scene.ts';
import { toRgba8 } from '../../tracer/quantize.ts';
import type { QuizPictures } from '../game/quiz-pictures.ts';

/**
 * The lab's side of picture predictions: each scene rendered by the services' picture worker
 * and quantized as the render window shows an image (its dithering and encoding included).
 */
export function quizPictureDrawer(services: () => LabServices): QuizPictures {
  return {
    async draw(scene: Scene): Promise<ImageData | null> {
      try {
        const image = await services().renderPicture(scene);
        const rgba = toRgba8(image.rgb, image.width, image.height, scene.settings) as Uint8ClampedArray<ArrayBuffer>;
        return new ImageData(rgba, image.width, image.height);
      } catch {
        return null;
      }
    },
  };
}
