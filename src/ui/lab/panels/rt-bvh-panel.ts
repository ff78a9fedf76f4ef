import { msg, str } from '@lit/localize';
import { css, html, nothing, type PropertyValues } from 'lit';
import type { LabAction } from '../../../lab-state/lab-action.ts';
import { type LabState, BVH_MAX_DEPTH, type BvhViewOptions } from '../../../lab-state/lab-state.ts';
import { loadMeshes } from '../../../render/load-meshes-browser.ts';
import { localNumbers } from '../../../i18n/number-format.ts';
import { bvhBoxesCounted, trianglesCounted } from '../../../i18n/counted.ts';
import type { MeshLibrary } from '../../../scene/mesh-data.ts';
import { meshNamesInScene } from '../../../scene/mesh-names.ts';
import type { Scene } from '../../../scene/scene.ts';
import { itemName } from '../scene-names.ts';
import { bvhTree, nodesAtDepth } from '../../../tracer/bvh-tree.ts';
import { meshAccel } from '../../../tracer/shapes/mesh-accel.ts';
import { buildTracerScene, type TracerScene } from '../../../tracer/tracer-scene.ts';
import { countPixelTests, type RayTests } from '../../../tracer/triangle-test-count.ts';
import { boxesLine, rayTestsHeadline } from './bvh-ray-wording.ts';
import { StorePanel } from './store-panel.ts';

/** What the panel found for the current scene: the tests of the selected pixel's ray, and the boxes at the chosen depth. */
interface Counts {
  scene: Scene;
  pixel: readonly [number, number] | null;
  depth: number;
  tests: RayTests | null;
  /** Boxes drawn at the chosen depth, per mesh object id. */
  boxes: Map<string, number>;
}

const NUMBER = localNumbers();

/**
 * @summary The acceleration panel: show every object's bounding box, show the BVH of the
 * models down to a depth, and, for the selected pixel's primary ray, how many boxes and
 * triangles the ray tracer tests ("This ray tested 12 of 8,624 triangles").
 *
 * The counts are computed here, on the main thread, by walking the tracer's own BVH of each
 * model the way its ray cast does (src/tracer/triangle-test-count.ts): one ray takes well
 * under a millisecond. The models' BVHs are built once per page (about 50–130 ms for the
 * 8,624-triangle character) the first time a scene with them needs counting.
 */
export class RtBvhPanel extends StorePanel<'bvh'> {
  protected readonly controlPanel = 'bvh';

  static override properties = {
    ...StorePanel.properties,
    counts: { state: true },
    failure: { state: true },
  };

  static override styles = [
    StorePanel.styles,
    css`
      .counts {
        margin: 4px 0 8px;
        display: grid;
        gap: 4px;
      }
      .counts p {
        margin: 0;
      }
      .headline {
        font-weight: 600;
      }
      .counts ul {
        margin: 0;
        padding-left: 18px;
      }
    `,
  ];

  /** How models are loaded (the browser's fetch by default; tests may swap it). */
  loader: (names: Iterable<string>) => Promise<MeshLibrary> = loadMeshes;
  declare private counts: Counts | null;
  declare private failure: string | null;
  private request = 0;
  private readonly prepared = new WeakMap<Scene, TracerScene>();

  constructor() {
    super();
    this.counts = null;
    this.failure = null;
  }

  protected override updated(changed: PropertyValues<this>): void {
    super.updated(changed);
    const state = this.state;
    const counts = this.counts;
    if (state && (!counts || counts.scene !== state.scene || counts.pixel !== state.selectedPixel || counts.depth !== state.bvh.depth)) {
      void this.count(state);
    }
  }

  /** Counts the tests of the selected pixel's ray and the boxes at the chosen depth, once the models are loaded. */
  private async count(state: LabState): Promise<void> {
    const request = ++this.request;
    const { scene, selectedPixel: pixel } = state;
    const depth = state.bvh.depth;
    let meshes: MeshLibrary;
    try {
      meshes = await this.loader(meshNamesInScene(scene));
    } catch (error) {
      if (request === this.request) this.failure = error instanceof Error ? error.message : String(error);
      return;
    }
    if (request !== this.request) return;
    let traced = this.prepared.get(scene);
    if (!traced) {
      traced = buildTracerScene(scene, meshes);
      this.prepared.set(scene, traced);
    }
    const boxes = new Map<string, number>();
    for (const object of scene.objects) {
      const model = object.mesh === undefined ? undefined : meshes.get(object.mesh);
      if (object.shape === 'mesh' && model) boxes.set(object.id, nodesAtDepth(bvhTree(meshAccel(model).bvh), depth).length);
    }
    this.failure = null;
    this.counts = { scene, pixel, depth, tests: pixel ? countPixelTests(traced, meshes, pixel) : null, boxes };
  }

  override render() {
    const state = this.state;
    if (!state) return html``;
    const bvh = state.bvh;
    const set = (changes: Partial<BvhViewOptions>): LabAction => ({ type: 'bvh.changed', changes });
    return html`
      ${this.section(msg('Boxes'), 'bvh', [
        this.switch(
          {
            name: 'bounds',
            label: msg('Show bounding boxes'),
            tooltip: msg(
              'Draw the box around every object (dashed). A ray that misses an object’s box cannot hit the object, so the ray tracer tests the box first.',
            ),
          },
          bvh.showBounds,
          (showBounds) => set({ showBounds }),
        ),
        this.switch(
          {
            name: 'show',
            label: msg('Show the BVH'),
            tooltip: msg(
              'Draw the boxes inside boxes (the bounding volume hierarchy) that the ray tracer uses for models made of triangles. With a model selected, only its boxes.',
            ),
          },
          bvh.show,
          (show) => set({ show }),
        ),
        this.slider(
          {
            name: 'depth',
            label: msg('Depth'),
            tooltip: msg(
              'How deep into the BVH to draw: 0 is one box around the whole model; each step divides every box’s triangles into two groups, each with its own box (boxes may overlap).',
            ),
            min: 0,
            max: BVH_MAX_DEPTH,
            step: 1,
            whole: true,
            disabled: !bvh.show,
          },
          bvh.depth,
          (depth) => set({ depth }),
          this.depthHint(bvh.depth),
        ),
      ])}
      ${this.section(msg('This ray’s tests'), 'bvh-ray', [this.rayCounts(state)])}
    `;
  }

  /** "0 = the whole model", and how many boxes the chosen depth has. */
  private depthHint(depth: number): string {
    const counts = this.counts;
    const sizes = counts && counts.depth === depth ? [...counts.boxes.values()] : [];
    const whole = msg('0 = the whole model.');
    if (sizes.length !== 1) return whole;
    const boxes = sizes[0] === 1 ? msg('At this depth: 1 box.') : msg(str`At this depth: ${NUMBER.format(sizes[0])} boxes.`);
    return `${whole} ${boxes}`;
  }

  private rayCounts(state: LabState) {
    if (this.failure) return html`<p class="counts" role="alert">${msg(str`The models could not be loaded: ${this.failure}`)}</p>`;
    const pixel = state.selectedPixel;
    if (!pixel) return html`<p class="counts muted">${msg('Select a pixel of the camera’s screen to count what its ray tests.')}</p>`;
    const counts = this.counts;
    const tests = counts && counts.scene === state.scene && counts.pixel === pixel ? counts.tests : null;
    if (!tests) return html`<p class="counts muted" role="status">${msg('Counting…')}</p>`;
    const models = tests.objects.filter((object) => object.mesh !== null);
    return html`<div class="counts" role="status" data-triangles=${tests.triangles} data-brute-force=${tests.bruteForce}>
      <p class="headline">${rayTestsHeadline(tests)}</p>
      <p>${boxesLine(pixel, tests, (id) => itemName(state.scene, id))}</p>
      ${
        models.length > 0
          ? html`<ul>
            ${models.map((object) => {
              const name = itemName(state.scene, object.id);
              const mesh = object.mesh!;
              return html`<li>
                ${
                  object.boundsHit
                    ? msg(
                        str`${name}: ${bvhBoxesCounted(mesh.boxes, NUMBER.format(mesh.boxes))} and ${trianglesCounted(mesh.triangles, NUMBER.format(mesh.triangles))} tested.`,
                      )
                    : msg(str`${name}: its bounding box was missed, so not one of its triangles was tested.`)
                }
              </li>`;
            })}
          </ul>`
          : nothing
      }
      <p>${tests.hitId === null ? msg('The ray hits nothing.') : msg(str`The ray hits ${itemName(state.scene, tests.hitId)}.`)}</p>
      ${
        state.bvh.show && tests.triangles > 0
          ? html`<p class="muted">${msg('In the view: the boxes this ray went into are solid green; the ones it tested and missed are dashed red, and everything inside them was skipped.')}</p>`
          : nothing
      }
    </div>`;
  }
}

customElements.define('rt-bvh-panel', RtBvhPanel);

declare global {
  interface HTMLElementTagNameMap {
    'rt-bvh-panel': RtBvhPanel;
  }
}
