import {
  BackSide,
  BufferGeometry,
  CircleGeometry,
  Color,
  ConeGeometry,
  CylinderGeometry,
  DoubleSide,
  Float32BufferAttribute,
  FrontSide,
  Group,
  Line,
  LineBasicMaterial,
  LineLoop,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  Object3D,
  PlaneGeometry,
  SphereGeometry,
} from 'three';
import type { Light, Scene } from '../scene/scene.ts';
import { setPickTag } from './picking.ts';
import { RADIANS_PER_DEGREE } from '../util/angles.ts';
import { sceneEuler } from '../tracer/scene-rotation.ts';

/** The drawn length of a spot light's cone along its sides (metres): a fixed slant keeps a 170° cone from growing huge. */
export const SPOT_CONE_SLANT = 0.9;
const BULB_RADIUS = 0.1;
const SPOT_BULB_RADIUS = 0.07;
/** A dark rim around bright shapes, so a white bulb stays visible on a light background. */
const RIM = 0x1b2330;
/** A light whose type is switched off in the ray tracer's settings is drawn faded and grey. */
const OFF_COLOR = new Color(0.55, 0.58, 0.62);
/** Lines in the light's colour are drawn this much darker than its surfaces. */
const EDGE_SHADE = 0.6;

interface Gizmo {
  /** Placed and turned like the light: the transform gizmo attaches here. */
  rig: Group;
  /** The key it was built for: type (and area shape); anything else is edited in place. */
  key: string;
  /**
   * Materials in the light's colour (times `shade`: edges are darker, so a white light's
   * cone still shows on a pale background), with their opacity when on; disposed with the gizmo.
   */
  tinted: { material: MeshBasicMaterial | LineBasicMaterial; opacity: number; shade: number }[];
  /** The part scaled by the spot angle or the area's size (so the rig itself keeps scale 1). */
  sized: Object3D | null;
}

/**
 * The scene's lights as gizmos (spec §1): a point light is a bulb; a spot light a bulb with
 * a cone whose half-angle is spotAngle/2 opening along local −Y; an area light a rectangle or
 * disc in its local XZ plane, lit face (toward −Y) in the light's colour, back face black.
 * Geometry is made once per kind and shared; a slider drag only edits scales and colours.
 */
export class LightGizmos {
  readonly group = new Group();
  private readonly gizmos = new Map<string, Gizmo>();
  private readonly shapes = lightShapes();
  private readonly rimMaterial = new MeshBasicMaterial({ color: RIM, side: BackSide });
  private readonly backMaterial = new MeshBasicMaterial({ color: 0x000000, side: BackSide });
  private readonly outlineMaterial = new LineBasicMaterial({ color: RIM });
  private readonly capMaterial = new MeshBasicMaterial({ color: 0x59616d });

  constructor() {
    this.group.name = 'light gizmos';
  }

  sync(scene: Scene): void {
    const seen = new Set<string>();
    for (const light of scene.lights) {
      seen.add(light.id);
      const key = light.type === 'area' ? `area:${light.shape}` : light.type;
      let gizmo = this.gizmos.get(light.id);
      if (gizmo && gizmo.key !== key) {
        this.remove(light.id, gizmo);
        gizmo = undefined;
      }
      if (!gizmo) {
        gizmo = this.build(light, key);
        this.gizmos.set(light.id, gizmo);
        this.group.add(gizmo.rig);
      }
      this.update(gizmo, light, scene.settings.lightTypes[light.type]);
    }
    for (const [id, gizmo] of this.gizmos) if (!seen.has(id)) this.remove(id, gizmo);
  }

  /** The rig of a light (for the transform gizmo), or undefined. */
  objectOf(id: string): Object3D | undefined {
    return this.gizmos.get(id)?.rig;
  }

  dispose(): void {
    for (const [id, gizmo] of this.gizmos) this.remove(id, gizmo);
    for (const geometry of Object.values(this.shapes)) geometry.dispose();
    this.rimMaterial.dispose();
    this.backMaterial.dispose();
    this.outlineMaterial.dispose();
    this.capMaterial.dispose();
  }

  private build(light: Light, key: string): Gizmo {
    const rig = new Group();
    rig.name = light.id;
    setPickTag(rig, { kind: 'light', id: light.id });
    const gizmo: Gizmo = { rig, key, tinted: [], sized: null };
    const tint = <M extends MeshBasicMaterial | LineBasicMaterial>(material: M, shade = 1): M => {
      gizmo.tinted.push({ material, opacity: material.opacity, shade });
      return material;
    };
    if (light.type !== 'area') {
      const radius = light.type === 'point' ? BULB_RADIUS : SPOT_BULB_RADIUS;
      const bulb = new Mesh(this.shapes.bulb, tint(new MeshBasicMaterial()));
      const rim = new Mesh(this.shapes.bulb, this.rimMaterial);
      bulb.scale.setScalar(radius);
      rim.scale.setScalar(radius * 1.18);
      rig.add(bulb, rim);
    }
    if (light.type === 'point') {
      // A screw cap on top makes the sphere read as a light bulb.
      const cap = new Mesh(this.shapes.cap, this.capMaterial);
      cap.scale.setScalar(BULB_RADIUS);
      rig.add(cap);
    }
    if (light.type === 'spot') {
      const cone = new Group();
      const surface = new MeshBasicMaterial({ transparent: true, opacity: 0.14, side: DoubleSide, depthWrite: false });
      cone.add(new Mesh(this.shapes.cone, tint(surface)), new LineSegments(this.shapes.coneEdges, tint(new LineBasicMaterial(), EDGE_SHADE)));
      rig.add(cone);
      gizmo.sized = cone;
    }
    if (light.type === 'area') {
      const disc = light.shape === 'disc';
      const panel = new Group();
      const front = new Mesh(disc ? this.shapes.disc : this.shapes.rectangle, tint(new MeshBasicMaterial({ side: FrontSide })));
      const back = new Mesh(front.geometry, this.backMaterial);
      const outline = new LineLoop(disc ? this.shapes.discOutline : this.shapes.rectangleOutline, this.outlineMaterial);
      panel.add(front, back, outline);
      // Which way it shines: a short line from the centre down its local −Y.
      rig.add(panel, new Line(this.shapes.emission, tint(new LineBasicMaterial(), EDGE_SHADE)));
      gizmo.sized = panel;
    }
    return gizmo;
  }

  private update(gizmo: Gizmo, light: Light, enabled: boolean): void {
    const rig = gizmo.rig;
    rig.position.set(...light.position);
    rig.scale.set(1, 1, 1);
    if (light.type !== 'point') sceneEuler(light.rotation, rig.rotation);
    if (light.type === 'spot' && gizmo.sized) {
      const half = (light.spotAngle / 2) * RADIANS_PER_DEGREE;
      const radius = SPOT_CONE_SLANT * Math.sin(half);
      gizmo.sized.scale.set(radius, SPOT_CONE_SLANT * Math.cos(half), radius);
    }
    if (light.type === 'area' && gizmo.sized) gizmo.sized.scale.set(light.size[0], 1, light.size[1]);
    color.setRGB(...light.color);
    if (!enabled) color.lerp(OFF_COLOR, 0.8);
    for (const { material, opacity, shade } of gizmo.tinted) {
      material.color.copy(color).multiplyScalar(shade);
      const transparent = opacity < 1 || !enabled;
      // Opaque and blended materials compile to different shaders.
      if (material.transparent !== transparent) material.needsUpdate = true;
      material.transparent = transparent;
      material.opacity = enabled ? opacity : opacity * 0.45;
    }
  }

  private remove(id: string, gizmo: Gizmo): void {
    this.group.remove(gizmo.rig);
    for (const { material } of gizmo.tinted) material.dispose();
    this.gizmos.delete(id);
  }
}

const color = new Color();

/** The shared unit shapes of the gizmos, each made once. */
function lightShapes() {
  return {
    bulb: new SphereGeometry(1, 24, 16),
    // A unit-radius bulb's cap: a short cylinder on top.
    cap: new CylinderGeometry(0.5, 0.55, 0.7, 16).translate(0, 1.15, 0),
    // Apex at the origin, base of radius 1 at y = −1 (ConeGeometry is centred, apex up).
    cone: new ConeGeometry(1, 1, 48, 1, true).translate(0, -0.5, 0),
    coneEdges: coneEdges(48),
    // Facing −Y: PlaneGeometry and CircleGeometry face +Z; +90° about X turns +Z into −Y.
    rectangle: new PlaneGeometry(1, 1).rotateX(Math.PI / 2),
    disc: new CircleGeometry(0.5, 48).rotateX(Math.PI / 2),
    rectangleOutline: loop([
      [-0.5, -0.5],
      [0.5, -0.5],
      [0.5, 0.5],
      [-0.5, 0.5],
    ]),
    discOutline: loop(Array.from({ length: 48 }, (_, i) => [0.5 * Math.cos((i / 48) * 2 * Math.PI), 0.5 * Math.sin((i / 48) * 2 * Math.PI)])),
    emission: new BufferGeometry().setAttribute('position', new Float32BufferAttribute([0, 0, 0, 0, -0.45, 0], 3)),
  };
}

/** A closed outline in the XZ plane through (x, z) points. */
function loop(points: number[][]): BufferGeometry {
  return new BufferGeometry().setAttribute(
    'position',
    new Float32BufferAttribute(
      points.flatMap(([x, z]) => [x, 0, z]),
      3,
    ),
  );
}

/** The cone's base circle and four lines from the apex, as line segments. */
function coneEdges(segments: number): BufferGeometry {
  const positions: number[] = [];
  const at = (i: number) => [Math.cos((i / segments) * 2 * Math.PI), -1, Math.sin((i / segments) * 2 * Math.PI)];
  for (let i = 0; i < segments; i++) positions.push(...at(i), ...at(i + 1));
  for (let i = 0; i < segments; i += segments / 4) positions.push(0, 0, 0, ...at(i));
  return new BufferGeometry().setAttribute('position', new Float32BufferAttribute(positions, 3));
}
