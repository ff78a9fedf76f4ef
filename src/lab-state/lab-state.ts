import type { Scene } from '../scene/scene.ts';
import type { DeclaredView } from './lab-action.ts';

/** What is selected in the lab: an object, a light, the ray tracer's camera, or nothing. */
export type Selection = { kind: 'object'; id: string } | { kind: 'light'; id: string } | { kind: 'camera' } | null;

/** The visualization options of the original tool's ray panel (spec §3 colours, issue: the lab). */
export interface RayViewOptions {
  showRays: boolean;
  /** Rays that hit nothing (drawn 10 m long in red). */
  hideNoHit: boolean;
  /** Rays whose contribution to their pixel is below `negligibleThreshold`. */
  hideNegligible: boolean;
  /** 0..1: the share of the pixel below which a ray counts as negligible. */
  negligibleThreshold: number;
  /** 0..1: 0 opaque rays, 1 almost invisible ones. */
  transparency: number;
  /** Radius of a drawn ray in metres (when not dynamic). */
  radius: number;
  /** Radius from contribution: minRadius at 0 %, maxRadius at 100 % (min > max is allowed). */
  dynamicRadius: boolean;
  minRadius: number;
  maxRadius: number;
  /** Darken each ray's colour by its contribution instead of its type colour alone. */
  contributionColor: boolean;
  /** The colour-blind-safe palette instead of VRT's. */
  colorBlindPalette: boolean;
  /** Rays grow from the camera. */
  animate: boolean;
  /** Metres per second of growth. */
  animationSpeed: number;
  /** One pixel after another instead of all at once. */
  animatePixelByPixel: boolean;
  loop: boolean;
  /** Show the s×s sub-pixel sample points on the camera's screen. */
  showSamplePoints: boolean;
  /** Colour the rays of a lens/time sample by their shutter time instead of their type (motion blur). */
  colorByTime: boolean;
}

/** The acceleration lessons' view: the tracer's BVH boxes and the objects' bounding boxes. */
export interface BvhViewOptions {
  /** Draw the BVH of mesh objects (the selected one, or all when no mesh is selected). */
  show: boolean;
  /** How deep into the tree to draw, 0 (the root: the whole model) to BVH_MAX_DEPTH. */
  depth: number;
  /** Draw every object's world bounding box (the box the tracer's slab test uses). */
  showBounds: boolean;
}

/** The deepest BVH level the view offers; trees of the shipped models are about this deep. */
export const BVH_MAX_DEPTH = 20;

export interface GizmoOptions {
  mode: 'translate' | 'rotate' | 'scale';
  space: 'local' | 'world';
  snap: boolean;
}

/** How a declared view asked the 3D view to look (what it frames, from where, or through the camera). */
export type ViewLook = Pick<DeclaredView, 'frame' | 'from' | 'throughCamera'>;

/** The one source of truth of the app: everything the view, the panels and the quest engine read. */
export interface LabState {
  scene: Scene;
  selection: Selection;
  /** The camera-screen pixel whose rays alone are shown, or null for all pixels. */
  selectedPixel: [number, number] | null;
  rays: RayViewOptions;
  gizmo: GizmoOptions;
  bvh: BvhViewOptions;
  /**
   * The last declared view's way of looking, a new object for each view that asks: the 3D
   * view follows it when it changes, and at once when it loads after it was set. Null after a
   * new scene, or a view that only sets pixels and filters.
   */
  look: ViewLook | null;
}

export const DEFAULT_RAY_VIEW: RayViewOptions = {
  showRays: true,
  hideNoHit: false,
  hideNegligible: false,
  negligibleThreshold: 0.01,
  transparency: 0,
  radius: 0.01,
  dynamicRadius: false,
  minRadius: 0.004,
  maxRadius: 0.03,
  contributionColor: false,
  colorBlindPalette: false,
  animate: false,
  animationSpeed: 4,
  animatePixelByPixel: false,
  loop: false,
  showSamplePoints: false,
  colorByTime: false,
};

export const DEFAULT_GIZMO: GizmoOptions = { mode: 'translate', space: 'world', snap: false };

export const DEFAULT_BVH_VIEW: BvhViewOptions = { show: false, depth: 2, showBounds: false };

export function initialState(scene: Scene): LabState {
  return { scene, selection: null, selectedPixel: null, rays: { ...DEFAULT_RAY_VIEW }, gizmo: { ...DEFAULT_GIZMO }, bvh: { ...DEFAULT_BVH_VIEW }, look: null };
}
