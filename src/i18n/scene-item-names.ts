import type { Scene } from '../scene/scene.ts';
import { localize, type LocalizedText } from '../util/localized-text.ts';
import { currentLocale } from './locale.ts';

/** A scene's, an object's or a light's name in the app's language ("Rode bal"), or `fallback` (its id) when it has none. */
export function shownName(name: LocalizedText | undefined, fallback: string): string {
  return name === undefined ? fallback : localize(name, currentLocale());
}

/** The name of the object or light with this id, as the scene list shows it; the id itself when nothing has it. */
export function itemName(scene: Scene, id: string): string {
  const item = scene.objects.find((object) => object.id === id) ?? scene.lights.find((light) => light.id === id);
  return shownName(item?.name, id);
}
