import {
  BoxGeometry,
  BufferAttribute,
  BufferGeometry,
  Color,
  CylinderGeometry,
  Group,
  Mesh,
  MeshPhongMaterial,
  type Object3D,
  PlaneGeometry,
  SphereGeometry,
} from 'three';
import type { MeshData, MeshLibrary } from '../scene/mesh-data.ts';
import type { Scene, SceneObject } from '../scene/scene.ts';
import { setPickTag } from './picking.ts';
import { useTracerFalloff } from './raster-falloff.ts';
import { ambientLight, applyRasterMaterial } from './raster-material.ts';
import { sceneEuler } from '../tracer/scene-rotation.ts';

/** Fetches the named models (the browser's loadMeshes; a stub in tests). */
export type MeshLoader = (names: Iterable<string>) => Promise<MeshLibrary>;

interface ObjectEntry {
  mesh: Mesh<BufferGeometry, MeshPhongMaterial>;
  /** The shape, or `mesh:<name>`: what the geometry was made for. */
  shapeKey: string;
}

/** An empty geometry for a model still downloading: the object appears when it arrives. */
const LOADING = new BufferGeometry();

/**
 * The scene's objects as three.js meshes, kept in step with the store incrementally: an
 * object's transform and material are edited in place, its geometry is shared by every
 * object of its shape (the unit shapes of spec §1, one per kind, made once), and only a
 * removed object's material is disposed. A slider drag therefore allocates nothing.
 */
export class SceneSync {
  readonly group = new Group();
  private readonly entries = new Map<string, ObjectEntry>();
  private readonly unitShapes = {
    sphere: new SphereGeometry(0.5, 48, 32),
    box: new BoxGeometry(1, 1, 1),
    cylinder: new CylinderGeometry(0.5, 0.5, 1, 48),
    // The unit square in XZ with normal +Y (PlaneGeometry lies in XY facing +Z).
    plane: new PlaneGeometry(1, 1).rotateX(-Math.PI / 2),
  };
  /** Model geometries by asset name, shared by every object showing that model. */
  private readonly models = new Map<string, BufferGeometry>();
  private readonly requested = new Set<string>();
  private readonly ambient = new Color();
  private disposed = false;

  /**
   * @param loadMeshes downloads models the scene uses for the first time.
   * @param onChange called when something changes outside a sync (a model arrived, or failed).
   */
  constructor(
    private readonly loadMeshes: MeshLoader,
    private readonly onChange: (error?: string) => void,
  ) {
    this.group.name = 'objects';
  }

  /** Brings the meshes in line with `scene.objects`. */
  sync(scene: Scene): void {
    ambientLight(scene, this.ambient);
    const seen = new Set<string>();
    for (const object of scene.objects) {
      seen.add(object.id);
      this.syncObject(object);
    }
    for (const [id, entry] of this.entries) {
      if (seen.has(id)) continue;
      this.group.remove(entry.mesh);
      entry.mesh.material.dispose();
      this.entries.delete(id);
    }
    this.releaseUnusedModels(scene);
  }

  /** The drawn mesh of an object (for the gizmo), or undefined. */
  objectOf(id: string): Object3D | undefined {
    return this.entries.get(id)?.mesh;
  }

  dispose(): void {
    this.disposed = true;
    for (const entry of this.entries.values()) entry.mesh.material.dispose();
    for (const geometry of Object.values(this.unitShapes)) geometry.dispose();
    for (const geometry of this.models.values()) geometry.dispose();
    this.entries.clear();
    this.models.clear();
    this.group.clear();
  }

  private syncObject(object: SceneObject): void {
    let entry = this.entries.get(object.id);
    if (!entry) {
      const mesh = new Mesh(LOADING, new MeshPhongMaterial());
      useTracerFalloff(mesh.material);
      mesh.name = object.id;
      setPickTag(mesh, { kind: 'object', id: object.id });
      entry = { mesh, shapeKey: '' };
      this.entries.set(object.id, entry);
      this.group.add(mesh);
    }
    const shapeKey = object.shape === 'mesh' ? `mesh:${object.mesh ?? ''}` : object.shape;
    if (entry.shapeKey !== shapeKey) {
      entry.shapeKey = shapeKey;
      entry.mesh.geometry = this.geometryFor(object);
    }
    const mesh = entry.mesh;
    mesh.position.set(...object.position);
    sceneEuler(object.rotation, mesh.rotation);
    mesh.scale.set(...object.scale);
    // A plane is seen from both sides (spec §1); models may be open surfaces (a wine glass).
    applyRasterMaterial(mesh.material, object.material, this.ambient, object.shape === 'plane' || object.shape === 'mesh');
  }

  private geometryFor(object: SceneObject): BufferGeometry {
    if (object.shape !== 'mesh') return this.unitShapes[object.shape];
    const name = object.mesh ?? '';
    const model = this.models.get(name);
    if (model) return model;
    this.request(name);
    return LOADING;
  }

  private request(name: string): void {
    if (this.requested.has(name)) return;
    this.requested.add(name);
    this.loadMeshes([name]).then(
      (library) => {
        const data = library.get(name);
        if (this.disposed || !data) return;
        this.models.set(name, modelGeometry(data));
        // Every object waiting for this model takes it now.
        for (const entry of this.entries.values()) {
          if (entry.shapeKey === `mesh:${name}`) entry.mesh.geometry = this.models.get(name)!;
        }
        this.onChange();
      },
      (error: unknown) => {
        this.requested.delete(name);
        this.onChange(error instanceof Error ? error.message : String(error));
      },
    );
  }

  /** Frees the GPU copy of a model no object shows any more. */
  private releaseUnusedModels(scene: Scene): void {
    for (const [name, geometry] of this.models) {
      if (scene.objects.some((o) => o.shape === 'mesh' && o.mesh === name)) continue;
      geometry.dispose();
      this.models.delete(name);
      this.requested.delete(name);
    }
  }
}

/** A model as indexed triangles; flat-shaded ones (no normals in the file) get face normals. */
export function modelGeometry(data: MeshData): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(data.positions, 3));
  geometry.setIndex(new BufferAttribute(data.indices, 1));
  if (data.normals) {
    geometry.setAttribute('normal', new BufferAttribute(data.normals, 3));
    return geometry;
  }
  // Face normals need unshared vertices: each triangle its own three.
  const flat = geometry.toNonIndexed();
  geometry.dispose();
  flat.computeVertexNormals();
  return flat;
}
