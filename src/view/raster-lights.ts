import { Group, Object3D, PointLight, SpotLight } from 'three';
import type { Light, Scene } from '../scene/scene.ts';
import { FOLLOWS_DISTANCE } from './raster-falloff.ts';
import { RADIANS_PER_DEGREE } from '../util/angles.ts';
import { sceneEuler } from '../tracer/scene-rotation.ts';

interface RasterLight {
  /** Placed and turned like the scene light; the three.js light sits at its origin. */
  holder: Object3D;
  light: PointLight | SpotLight;
  type: Light['type'];
}

/**
 * The scene's lights approximated for the raster look (no shadows, reflections or soft
 * light: that is what the ray tracer is for). Three.js's Phong divides diffuse by π, so a
 * light of intensity π·I·ld gives the tracer's I·ld·kd·C·(N·L). Spot and area lights become
 * spot lights along local −Y (an area light as a 180° cone). The view's materials shade with
 * the tracer's distance and angle attenuation per fragment (raster-falloff.ts): a light's
 * `decay` says whether distance attenuation is on, a spot's `distance` carries p.
 */
export class RasterLights {
  readonly group = new Group();
  private readonly entries = new Map<string, RasterLight>();

  constructor() {
    this.group.name = 'raster lights';
  }

  sync(scene: Scene): void {
    const seen = new Set<string>();
    for (const light of scene.lights) {
      seen.add(light.id);
      let entry = this.entries.get(light.id);
      if (entry && entry.type !== light.type) {
        this.remove(light.id, entry);
        entry = undefined;
      }
      if (!entry) {
        entry = this.create(light);
        this.entries.set(light.id, entry);
        this.group.add(entry.holder);
      }
      this.update(entry, light, scene.settings.lightTypes[light.type]);
    }
    for (const [id, entry] of this.entries) if (!seen.has(id)) this.remove(id, entry);
  }

  dispose(): void {
    for (const [id, entry] of this.entries) this.remove(id, entry);
  }

  private create(light: Light): RasterLight {
    const holder = new Object3D();
    if (light.type === 'point') {
      const point = new PointLight(0xffffff, 1, 0, 0);
      holder.add(point);
      return { holder, light: point, type: light.type };
    }
    const spot = new SpotLight(0xffffff, 1, 0, Math.PI / 4, 0, 0);
    spot.target.position.set(0, -1, 0);
    holder.add(spot, spot.target);
    return { holder, light: spot, type: light.type };
  }

  private update(entry: RasterLight, light: Light, enabled: boolean): void {
    entry.holder.position.set(...light.position);
    if (light.type !== 'point') sceneEuler(light.rotation, entry.holder.rotation);
    entry.light.visible = enabled;
    entry.light.color.setRGB(...light.color);
    entry.light.intensity = Math.PI * light.intensity * light.diffuse;
    entry.light.decay = light.distanceAttenuation ? FOLLOWS_DISTANCE : 0;
    if (entry.light instanceof SpotLight && light.type !== 'point') {
      entry.light.angle = light.type === 'spot' ? (light.spotAngle / 2) * RADIANS_PER_DEGREE : Math.PI / 2;
      entry.light.distance = light.angleAttenuation;
    }
  }

  private remove(id: string, entry: RasterLight): void {
    this.group.remove(entry.holder);
    entry.light.dispose();
    this.entries.delete(id);
  }
}
