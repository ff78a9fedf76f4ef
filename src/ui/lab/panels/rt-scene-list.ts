import { msg, str } from '@lit/localize';
import { css, html, nothing, type PropertyValues, type TemplateResult } from 'lit';
import { ifDefined } from 'lit/directives/if-defined.js';
import { repeat } from 'lit/directives/repeat.js';
import type { LabAction } from '../../../lab-state/lab-action.ts';
import type { Selection } from '../../../lab-state/lab-state.ts';
import { MESH_ASSET_NAMES } from '../../../scene/mesh-assets.ts';
import type { LightType } from '../../../scene/scene.ts';
import { isLocked, type MovableItems } from '../../../quest/movable-items.ts';
import { lockedNote } from '../../../view/locked-note.ts';
import { cameraIcon, lightIcon, lockIcon, shapeIcon } from '../scene-icons.ts';
import { itemName, lightTypeName, lightTypeShortName, modelName, shapeKindName, shapeName, shownName } from '../scene-names.ts';
import { visuallyHiddenStyles } from '../../controls/visually-hidden.css.ts';
import { StorePanel } from './store-panel.ts';
import { guideIds } from '../../../quest/lab-controls.ts';

/** One row of the list, in the order the arrow keys walk. */
interface Item {
  key: string;
  selection: Exclude<Selection, null>;
}

const SHAPES = ['sphere', 'box', 'cylinder', 'plane'] as const;
const LIGHT_TYPES: LightType[] = ['point', 'spot', 'area'];

/**
 * @summary The scene's objects, lights and camera as a list to select from, with Add and
 * Delete (hidden when `allowEditing` is false, as in the game's first levels).
 *
 * A single-select listbox: Tab enters it at the selected item; Up/Down, Home and End move
 * and select (the 3D view follows at once); Delete removes the selected item. Add opens
 * buttons for each shape, model and light type. Every change is a `selection.changed`,
 * `object.added`, `light.added`, `object.deleted` or `light.deleted` action on `store`.
 * `shownControls` (scene-list.objects, scene-list.lights) can leave out the objects or the
 * lights; the camera is always listed. `movable` (a level's ui.movable) locks the other items:
 * they carry a lock, cannot be deleted, and while one is selected the panel says why.
 */
export class RtSceneList extends StorePanel<'scene-list'> {
  protected readonly controlPanel = 'scene-list';
  static override properties = {
    ...StorePanel.properties,
    allowEditing: { type: Boolean, attribute: 'allow-editing' },
    movable: { attribute: false },
    adding: { state: true },
  };

  static override styles = [
    StorePanel.styles,
    visuallyHiddenStyles,
    css`
      [role='listbox'] {
        display: grid;
        margin: 0 -8px;
      }
      .group-label {
        padding: 8px 8px 4px;
        color: var(--rt-muted);
        font-size: 0.75rem;
        font-weight: 700;
        letter-spacing: 0.04em;
        text-transform: uppercase;
      }
      [role='option'] {
        display: flex;
        align-items: center;
        gap: 8px;
        min-height: var(--rt-target);
        padding: 0 8px;
        border-radius: 6px;
        cursor: pointer;
      }
      [role='option']:hover {
        background: var(--rt-bg);
      }
      [role='option'][aria-selected='true'] {
        background: var(--rt-accent);
        color: var(--rt-accent-text);
        font-weight: 600;
      }
      [role='option']:focus-visible {
        outline-offset: -3px;
      }
      [role='option'][aria-selected='true']:focus-visible {
        outline-color: var(--rt-text);
      }
      .icon {
        flex: none;
      }
      .name {
        flex: 1 1 auto;
        min-width: 0;
        overflow: hidden;
        text-overflow: ellipsis;
        white-space: nowrap;
      }
      .kind {
        flex: none;
        font-size: 0.8125rem;
        opacity: 0.8;
      }
      .locked-reason {
        margin: 8px 0 0;
        color: var(--rt-muted);
        font-size: 0.8125rem;
      }
      .actions {
        display: flex;
        gap: 8px;
      }
      .actions button {
        flex: 1 1 0;
      }
      .add {
        display: grid;
        gap: 8px;
        padding: 8px;
        border: 1px solid var(--rt-border);
        border-radius: 6px;
        background: var(--rt-bg);
      }
      .add fieldset {
        display: grid;
        grid-template-columns: 1fr 1fr;
        gap: 8px;
        margin: 0;
        padding: 0;
        border: 0;
        min-width: 0;
      }
      /* Floated, a legend is an ordinary grid item: a row of its own above the buttons. */
      .add legend {
        float: left;
        grid-column: 1 / -1;
        padding: 0;
        color: var(--rt-muted);
        font-size: 0.8125rem;
      }
      .add .lights {
        grid-template-columns: 1fr 1fr 1fr;
      }
      .add button {
        padding: 0 8px;
      }
    `,
  ];

  /** Show Add and Delete (default true); the game's early levels switch them off. */
  declare allowEditing: boolean;
  /** The only items that can be moved or deleted (undefined: all). */
  declare movable: MovableItems;
  /** Whether the Add buttons are open. */
  declare private adding: boolean;
  /** Focus the selected row after the next render (after adding or deleting by keyboard). */
  private focusSelected = false;

  constructor() {
    super();
    this.allowEditing = true;
    this.adding = false;
  }

  private items(): Item[] {
    const scene = this.state?.scene;
    if (!scene) return [];
    return [
      ...(this.shows('objects') ? scene.objects : []).map((o): Item => ({ key: `object:${o.id}`, selection: { kind: 'object', id: o.id } })),
      ...(this.shows('lights') ? scene.lights : []).map((l): Item => ({ key: `light:${l.id}`, selection: { kind: 'light', id: l.id } })),
      { key: 'camera', selection: { kind: 'camera' } },
    ];
  }

  private selectedKey(): string | undefined {
    const selection = this.state?.selection;
    if (!selection) return undefined;
    return selection.kind === 'camera' ? 'camera' : `${selection.kind}:${selection.id}`;
  }

  private select(item: Item): void {
    if (item.key !== this.selectedKey()) this.send('list', { type: 'selection.changed', selection: item.selection });
  }

  private onKeydown(event: KeyboardEvent): void {
    const items = this.items();
    const current = items.findIndex((item) => item.key === (event.target as HTMLElement).dataset['key']);
    const moves: Partial<Record<string, number>> = { ArrowDown: current + 1, ArrowUp: current - 1, Home: 0, End: items.length - 1 };
    const next = moves[event.key];
    if (next !== undefined) {
      event.preventDefault();
      const item = items[Math.max(0, Math.min(items.length - 1, next))];
      this.select(item);
      this.optionFor(item.key)?.focus();
    } else if ((event.key === 'Enter' || event.key === ' ') && current >= 0) {
      event.preventDefault();
      this.select(items[current]);
    } else if (event.key === 'Delete' && this.allowEditing && current >= 0) {
      // Handled here: the lab's own Delete key must not delete a second time.
      event.stopPropagation();
      this.delete(items[current].selection);
    }
  }

  private optionFor(key: string): HTMLElement | null {
    return this.renderRoot.querySelector<HTMLElement>(`[role='option'][data-key='${CSS.escape(key)}']`);
  }

  private add(action: LabAction): void {
    this.adding = false;
    this.focusSelected = true;
    this.send('edit', action);
  }

  private delete(selection: Selection): void {
    // A locked item's reason is on show while it is selected.
    if (!selection || selection.kind === 'camera' || isLocked(selection, this.movable)) return;
    this.focusSelected = true;
    this.send('edit', selection.kind === 'object' ? { type: 'object.deleted', id: selection.id } : { type: 'light.deleted', id: selection.id });
  }

  protected override updated(changed: PropertyValues<this>): void {
    super.updated(changed);
    if (!this.focusSelected) return;
    this.focusSelected = false;
    this.renderRoot.querySelector<HTMLElement>("[role='option'][tabindex='0']")?.focus();
  }

  override render() {
    const scene = this.state?.scene;
    if (!scene) return html``;
    const selected = this.selectedKey();
    // Roving tabindex: Tab lands on the selected row, or the first when nothing is selected.
    const tabStop = selected ?? this.items()[0]?.key;
    const reason = this.lockedReason();
    const option = (key: string, icon: TemplateResult, name: string, kind: string, selection: Exclude<Selection, null>, guide: string) => {
      const locked = isLocked(selection, this.movable);
      return html`<div
        role="option"
        id=${key}
        data-key=${key}
        data-guide=${guide}
        tabindex=${key === tabStop ? 0 : -1}
        aria-selected=${key === selected ? 'true' : 'false'}
        aria-describedby=${ifDefined(key === selected && reason ? 'locked-reason' : undefined)}
        ?data-locked=${locked}
        @click=${() => this.select({ key, selection })}
      >
        ${icon}<span class="name">${name}</span><span class="kind">${kind}</span>${locked ? html`${lockIcon()}<span class="visually-hidden">${msg('locked')}</span>` : nothing}
      </div>`;
    };
    const off = (type: LightType) => (scene.settings.lightTypes[type] ? '' : ` (${msg('off')})`);
    return html`
      <rt-panel-section heading=${msg('Scene')} name="scene">
        <div role="listbox" aria-label=${msg('Objects, lights and camera')} @keydown=${this.onKeydown}>
          ${
            this.shows('objects')
              ? html`<div role="group" aria-labelledby="objects-label">
                <div role="presentation" class="group-label" id="objects-label">${msg('Objects')}</div>
                ${repeat(
                  scene.objects,
                  (o) => o.id,
                  (o) =>
                    option(
                      `object:${o.id}`,
                      shapeIcon(o.shape, o.material.color),
                      shownName(o.name, o.id),
                      shapeName(o),
                      { kind: 'object', id: o.id },
                      `scene-list.objects scene-list.item:${o.id}`,
                    ),
                )}
              </div>`
              : nothing
          }
          ${
            this.shows('lights')
              ? html`<div role="group" aria-labelledby="lights-label">
                <div role="presentation" class="group-label" id="lights-label">${msg('Lights')}</div>
                ${repeat(
                  scene.lights,
                  (l) => l.id,
                  (l) =>
                    option(
                      `light:${l.id}`,
                      lightIcon(l.type, l.color),
                      shownName(l.name, l.id),
                      lightTypeName(l.type) + off(l.type),
                      { kind: 'light', id: l.id },
                      `scene-list.lights scene-list.item:${l.id}`,
                    ),
                )}
              </div>`
              : nothing
          }
          <div role="group" aria-labelledby="camera-label">
            <div role="presentation" class="group-label" id="camera-label">${msg('Camera')}</div>
            ${option('camera', cameraIcon(), msg('Ray tracer camera'), '', { kind: 'camera' }, 'scene-list.item:camera')}
          </div>
        </div>
        ${reason ? html`<p class="locked-reason" id="locked-reason" data-testid="locked-reason">${reason}</p>` : nothing}
        ${this.errorLine('list')}
        ${this.allowEditing ? this.editing() : nothing}
      </rt-panel-section>
    `;
  }

  /** Why the selected item stays where it is (a level's ui.movable), or '' when it is free to move. */
  private lockedReason(): string {
    const selection = this.state?.selection ?? null;
    if (!this.state || !selection || !this.movable || !isLocked(selection, this.movable)) return '';
    return lockedNote(this.state.scene, selection, this.movable);
  }

  private editing(): TemplateResult {
    const selection = this.state?.selection ?? null;
    const deletable = selection !== null && selection.kind !== 'camera' && !isLocked(selection, this.movable);
    const label = deletable
      ? msg(str`Delete ${this.state ? itemName(this.state.scene, selection.id) : selection.id}`)
      : msg('Select an object or a light to delete it');
    return html`
      <div class="actions">
        <button type="button" data-guide=${guideIds('add-remove.add-object', 'add-remove.add-light')} aria-expanded=${this.adding ? 'true' : 'false'} aria-controls="add" @click=${() => (this.adding = !this.adding)}>
          ${this.adding ? '−' : '+'} ${msg('Add')}
        </button>
        <button type="button" data-guide=${guideIds('add-remove.delete')} title=${label} ?disabled=${!deletable} @click=${() => this.delete(selection)}>${msg('Delete')}</button>
      </div>
      ${this.adding ? this.addButtons() : nothing}
      ${this.errorLine('edit')}
    `;
  }

  private addButtons(): TemplateResult {
    const button = (label: string, title: string, action: LabAction) =>
      html`<button type="button" title=${title} @click=${() => this.add(action)}>${label}</button>`;
    return html`<div class="add" id="add">
      <fieldset data-guide=${guideIds('add-remove.add-object')}>
        <legend>${msg('Shapes')}</legend>
        ${SHAPES.map((shape) => button(shapeKindName(shape), msg(str`Add ${shapeKindName(shape)} to the scene`), { type: 'object.added', shape }))}
      </fieldset>
      <fieldset data-guide=${guideIds('add-remove.add-object')}>
        <legend>${msg('Models')}</legend>
        ${MESH_ASSET_NAMES.map((mesh) => button(modelName(mesh), msg(str`Add the ${modelName(mesh)} model to the scene`), { type: 'object.added', shape: 'mesh', mesh }))}
      </fieldset>
      <fieldset class="lights" data-guide=${guideIds('add-remove.add-light')}>
        <legend>${msg('Lights')}</legend>
        ${LIGHT_TYPES.map((lightType) => button(lightTypeShortName(lightType), msg(str`Add ${lightTypeName(lightType)} to the scene`), { type: 'light.added', lightType }))}
      </fieldset>
    </div>`;
  }
}

customElements.define('rt-scene-list', RtSceneList);

declare global {
  interface HTMLElementTagNameMap {
    'rt-scene-list': RtSceneList;
  }
}
