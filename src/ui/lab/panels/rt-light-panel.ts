import { msg, str } from '@lit/localize';
import { html, nothing } from 'lit';
import type { LabAction } from '../../../lab-state/lab-action.ts';
import type { AreaLight, Light, LightType, SpotLight } from '../../../scene/scene.ts';
import { LIMITS } from '../../../scene/scene-limits.ts';
import { positionSpec, rotationSpec } from './placement-specs.ts';
import { lightTypeName, lightTypeShortName, shownName } from '../scene-names.ts';
import { StorePanel, type ControlPart } from './store-panel.ts';

/**
 * @summary The selected light: its type (changing it keeps the shared fields), colour,
 * intensity, its ambient/diffuse/specular shares, distance attenuation, and per type the
 * spot angle, angle attenuation, the area's samples (shown as n × n shadow rays), size and
 * shape; then position and, for spot and area lights, rotation. With no light selected it
 * says how to select one.
 *
 * Every edit is a `light.changed` action on `store`; a refused edit's reason is shown next
 * to its control and the control keeps the store's value.
 */
export class RtLightPanel extends StorePanel<'light'> {
  protected readonly controlPanel = 'light';

  override render() {
    const selection = this.state?.selection;
    const light = selection?.kind === 'light' ? this.state?.scene.lights.find((l) => l.id === selection.id) : undefined;
    if (!light) {
      return this.emptyState(
        msg('Light'),
        'light',
        msg('Select a light in the scene or in the list.'),
        msg('Lights are the bulb, cone and panel shapes in the 3D view.'),
      );
    }
    const changed = (changes: Partial<Light>): LabAction => ({ type: 'light.changed', id: light.id, changes });
    const controls: ControlPart[] = [
      this.choice<LightType>(
        { name: 'type', label: msg('Type'), tooltip: msg('Point: from one point. Spot: a cone. Area: a panel that casts soft shadows.') },
        [
          { value: 'point', label: lightTypeShortName('point'), tooltip: msg('Light from one point, in every direction: hard shadows.') },
          { value: 'spot', label: lightTypeShortName('spot'), tooltip: msg('A cone of light, like a desk lamp.') },
          { value: 'area', label: lightTypeShortName('area'), tooltip: msg('A glowing rectangle or disc: soft shadows.') },
        ],
        light.type,
        (type) => changed({ type }),
      ),
      this.color({ name: 'color', label: msg('Colour'), tooltip: msg('The colour of the light, as red, green and blue from 0 to 1.') }, light.color, (color) =>
        changed({ color }),
      ),
      this.slider(
        {
          name: 'intensity',
          label: msg('Intensity (I)'),
          tooltip: msg('How strong the light is. Type up to 100 (for far objects with distance attenuation).'),
          min: 0,
          max: 30,
          step: 0.05,
          inputMax: LIMITS.intensity[1],
        },
        light.intensity,
        (intensity) => changed({ intensity }),
      ),
      ...this.phongSliders(
        {
          ambient: [msg('Ambient'), msg('How much ambient light it adds everywhere, even in shadow.')],
          diffuse: [msg('Diffuse'), msg('How much it lights surfaces that face it (matte shading).')],
          specular: [msg('Specular'), msg('How bright the highlights it makes are.')],
        },
        light,
        changed,
      ),
      this.switch(
        {
          name: 'distanceAttenuation',
          label: msg('Distance attenuation'),
          tooltip: msg('Multiply the light by A = 1 / (0.04 + 0.1·d + 0.06·d²) at distance d: above 1 closer than about 3.3 m, below 1 further away.'),
        },
        light.distanceAttenuation,
        (distanceAttenuation) => changed({ distanceAttenuation }),
      ),
      ...(light.type === 'spot' ? this.spotControls(light, changed) : []),
      ...(light.type === 'area' ? this.areaControls(light, changed) : []),
    ];
    return html`
      ${this.section(msg('Light'), 'light', controls, this.identity(shownName(light.name, light.id), lightTypeName(light.type)))}
      ${this.section(msg('Placement'), 'light-placement', [
        this.vector(positionSpec(), light.position, (position) => changed({ position })),
        light.type === 'point' ? nothing : this.vector(rotationSpec(), light.rotation, (rotation) => changed({ rotation })),
      ])}
    `;
  }

  private angleAttenuation(light: SpotLight | AreaLight, changed: (changes: Partial<Light>) => LabAction): ControlPart {
    return this.slider(
      {
        name: 'angleAttenuation',
        label: msg('Angle attenuation (p)'),
        tooltip: msg('p in cos(α)^p, where α is the angle between where the spot points and the direction to the point.'),
        min: LIMITS.angleAttenuation[0],
        max: LIMITS.angleAttenuation[1],
        step: 0.5,
      },
      light.angleAttenuation,
      (angleAttenuation) => changed({ angleAttenuation }),
    );
  }

  private spotControls(light: SpotLight, changed: (changes: Partial<Light>) => LabAction): ControlPart[] {
    return [
      this.slider(
        {
          name: 'spotAngle',
          label: msg('Spot angle'),
          tooltip: msg('The full opening angle of the cone, in degrees.'),
          min: LIMITS.spotAngle[0],
          max: LIMITS.spotAngle[1],
          step: 1,
          unit: '°',
        },
        light.spotAngle,
        (spotAngle) => changed({ spotAngle }),
      ),
      this.angleAttenuation(light, changed),
    ];
  }

  private areaControls(light: AreaLight, changed: (changes: Partial<Light>) => LabAction): ControlPart[] {
    const n = light.samples;
    return [
      this.angleAttenuation(light, changed),
      this.slider(
        {
          name: 'samples',
          label: msg('Samples per side (n)'),
          tooltip: msg('n × n shadow rays from each point to the light: more give smoother soft shadows, but take longer.'),
          min: LIMITS.areaSamples[0],
          max: LIMITS.areaSamples[1],
          step: 1,
          whole: true,
        },
        n,
        (samples) => changed({ samples }),
        n === 1 ? msg('1 shadow ray per point') : msg(str`${n} × ${n} = ${n * n} shadow rays per point`),
      ),
      this.vector(
        {
          name: 'size',
          label: msg('Size'),
          tooltip: msg('Width and depth of the light in metres (the diameters of a disc).'),
          axes: [msg('width'), msg('depth')],
          min: LIMITS.areaSize[0],
          max: LIMITS.areaSize[1],
          step: 0.01,
          unit: 'm',
        },
        light.size,
        (size) => changed({ size }),
      ),
      this.choice<AreaLight['shape']>(
        { name: 'shape', label: msg('Shape'), tooltip: msg('A rectangle or a disc (an ellipse when width and depth differ).') },
        [
          { value: 'rectangle', label: msg('Rectangle') },
          { value: 'disc', label: msg('Disc') },
        ],
        light.shape,
        (shape) => changed({ shape }),
      ),
    ];
  }
}

customElements.define('rt-light-panel', RtLightPanel);

declare global {
  interface HTMLElementTagNameMap {
    'rt-light-panel': RtLightPanel;
  }
}
