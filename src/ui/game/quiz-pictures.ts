import { createContext } from '@lit/context';
import type { Scene } from '../../scene/scene.ts';

/**
 * Draws a picture prediction's choices: the lab provides it (it owns the render workers),
 * each quiz asks it for the pixels of its scenes. Null: the picture could not be made.
 */
export interface QuizPictures {
  draw(scene: Scene): Promise<ImageData | null>;
}

export const quizPicturesContext = createContext<QuizPictures | undefined>(Symbol('quiz-pictures'));
