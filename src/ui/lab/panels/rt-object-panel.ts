import { msg } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { ifDefined } from 'lit/directives/if-defined.js';
import type { LabAction } from '../../../lab-state/lab-action.ts';
import type { Material, SceneObject } from '../../../scene/scene.ts';
import { LIMITS } from '../../../scene/scene-limits.ts';
import { MATERIAL_PRESETS, matchingPreset, type MaterialPresetName } from './material-presets.ts';
import { positionSpec, rotationSpec, scaleSpec } from './placement-specs.ts';
import { glossySamplesSpec, roughnessSpec, velocitySpec } from './distribution-specs.ts';
import { shapeName, shownName } from '../scene-names.ts';
import { StorePanel, type ControlPart } from './store-panel.ts';

/**
 * @summary The selected object's material and placement: colour, the Phong coefficients,
 * shininess, transparency with its refractive index, roughness and glossy samples, three
 * presets, and position, rotation, scale and velocity fields (the keyboard's way to do what the gizmo does). With no object
 * selected it says how to select one.
 *
 * Every edit is a `material.changed` or `object.changed` action on `store`; a refused
 * edit's reason is shown next to its control and the control keeps the store's value.
 */
export class RtObjectPanel extends StorePanel<'object'> {
  protected readonly controlPanel = 'object';

  static override styles = [
    StorePanel.styles,
    css`
      .presets {
        display: flex;
        flex-wrap: wrap;
        align-items: center;
        gap: 8px;
      }
      .presets button {
        flex: 1 1 0;
        padding: 0 8px;
        white-space: nowrap;
      }
      .presets-label {
        flex-basis: 100%;
      }
    `,
  ];

  override render() {
    const selection = this.state?.selection;
    const object = selection?.kind === 'object' ? this.state?.scene.objects.find((o) => o.id === selection.id) : undefined;
    if (!object) {
      return this.emptyState(
        msg('Object'),
        'object',
        msg('Select an object in the scene or in the list.'),
        msg('Click it in the 3D view, or use the arrow keys in the scene list.'),
      );
    }
    return html`
      ${this.section(msg('Object'), 'object', this.materialControls(object), this.identity(shownName(object.name, object.id), shapeName(object)))}
      ${this.section(msg('Placement'), 'object-placement', [
        this.vector(positionSpec(), object.position, (position) => this.changed(object, { position })),
        this.vector(rotationSpec(), object.rotation, (rotation) => this.changed(object, { rotation })),
        this.vector(scaleSpec(), object.scale, (scale) => this.changed(object, { scale })),
        this.vector(velocitySpec(), object.velocity, (velocity) => this.changed(object, { velocity })),
      ])}
    `;
  }

  private materialControls(object: SceneObject): ControlPart[] {
    const m = object.material;
    const material = (changes: Partial<Material>): LabAction => ({ type: 'material.changed', id: object.id, changes });
    return [
      this.color(
        { name: 'color', label: msg('Colour'), tooltip: msg('The surface colour, as red, green and blue from 0 to 1 (#ff0000 is 1, 0, 0).') },
        m.color,
        (color) => material({ color }),
      ),
      ...this.phongSliders(
        {
          ambient: [msg('Ambient (ka)'), msg('How much of the lights’ ambient light it reflects everywhere, even in shadow.')],
          diffuse: [msg('Diffuse (kd)'), msg('Matte reflection: light scattered equally in every direction.')],
          specular: [msg('Specular (ks)'), msg('Strength of the highlight; on an opaque object also how much it mirrors.')],
        },
        m,
        material,
      ),
      this.slider(
        {
          name: 'shininess',
          label: msg('Shininess (n)'),
          tooltip: msg('The Phong exponent n in (R·V)^n. Type up to 10000.'),
          min: 0,
          max: 1000,
          step: 1,
          inputMax: LIMITS.shininess[1],
        },
        m.shininess,
        (shininess) => material({ shininess }),
      ),
      this.switch(
        { name: 'transparent', label: msg('Transparent'), tooltip: msg('Let light through: rays refract into the object, and partly reflect (Schlick).') },
        m.transparent,
        (transparent) => material({ transparent }),
      ),
      this.slider(
        {
          name: 'refractiveIndex',
          label: msg('Refractive index (η)'),
          tooltip: m.transparent
            ? msg('n in Snell’s law n₁·sin θ₁ = n₂·sin θ₂: air 1, water 1.33, glass 1.5, diamond 2.42. Type up to 4.')
            : msg('n in Snell’s law. Switch on Transparent to use it.'),
          min: 1,
          max: 3,
          step: 0.01,
          inputMax: LIMITS.refractiveIndex[1],
          disabled: !m.transparent,
        },
        m.refractiveIndex,
        (refractiveIndex) => material({ refractiveIndex }),
      ),
      this.slider(roughnessSpec(), m.roughness, (roughness) => material({ roughness })),
      this.slider(glossySamplesSpec(m.roughness === 0), m.glossySamples, (glossySamples) => material({ glossySamples })),
      this.presets(object),
    ];
  }

  private presets(object: SceneObject): ControlPart {
    if (!this.shows('presets')) return nothing;
    const current = matchingPreset(object.material);
    const labels: Record<MaterialPresetName, [string, string]> = {
      opaque: [msg('Opaque'), msg('Matte with the default finish; keeps the colour.')],
      mirror: [msg('Mirror'), msg('Little diffuse, strong specular: reflects its surroundings; keeps the colour.')],
      glass: [msg('Glass'), msg('Transparent with η 1.5 and a sharp highlight; keeps the colour.')],
    };
    return html`<div class="presets" role="group" aria-labelledby="presets-label" data-guide=${ifDefined(this.guideOf('presets'))}>
      <span class="presets-label" id="presets-label">${msg('Presets')}</span>
      ${(Object.keys(MATERIAL_PRESETS) as MaterialPresetName[]).map(
        (name) => html`<button
          type="button"
          title=${labels[name][1]}
          aria-pressed=${current === name ? 'true' : 'false'}
          @click=${() => this.send('presets', { type: 'material.changed', id: object.id, changes: { ...MATERIAL_PRESETS[name] } })}
        >
          ${current === name ? '✓ ' : ''}${labels[name][0]}
        </button>`,
      )}
    </div>
    ${this.errorLine('presets')}`;
  }

  private changed(object: SceneObject, changes: Partial<Omit<SceneObject, 'id' | 'material'>>): LabAction {
    return { type: 'object.changed', id: object.id, changes };
  }
}

customElements.define('rt-object-panel', RtObjectPanel);

declare global {
  interface HTMLElementTagNameMap {
    'rt-object-panel': RtObjectPanel;
  }
}
