import { LAB_CONTROLS, type LabPanel } from '../../../quest/lab-controls.ts';

/**
 * The level id (quest/lab-controls.ts) of a panel control by its element name: the name in
 * kebab case ("refractiveIndex" → "refractive-index"), its group for grouped names
 * ("pixels.columns" → "pixels"), or the panel's own spelling where that differs
 * (`renamed`: showRays → show). Undefined for a control levels cannot name (position fields).
 */
export function controlIdOf(panel: LabPanel, name: string, renamed: Readonly<Record<string, string>> = {}): string | undefined {
  const id = renamed[name] ?? kebabCase(name.split('.')[0] ?? name);
  return (LAB_CONTROLS[panel] as readonly string[]).includes(id) ? id : undefined;
}

/** "refractiveIndex" → "refractive-index". */
function kebabCase(name: string): string {
  return name.replace(/[A-Z]/g, (letter) => `-${letter.toLowerCase()}`);
}
