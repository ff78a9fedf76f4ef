import type { BufferGeometry } from 'three';

/** How to build one shipped model (assets/models/<name>.obj). */
export interface ModelRecipe {
  /** The asset name a scene uses in `"mesh": "<name>"`. */
  name: string;
  /** One sentence for the OBJ header and assets/README.md. */
  description: string;
  /**
   * The model with `position` and `normal` attributes, counter-clockwise faces facing
   * outward, up +Y and front +Z. Any size: make-models scales it to 1 m tall and centres it.
   */
  build(): BufferGeometry;
}
