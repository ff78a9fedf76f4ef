import { msg } from '@lit/localize';
import { css, html, nothing, type TemplateResult } from 'lit';

/**
 * The ray legend's key for a pixel's sample paths (path mode with a pixel chosen,
 * path-tracing spec §5): what the view's marks mean that no ray colour says — solid bounces,
 * dashed light samples (their swatches above switch to the same patterns, path-dashes.ts),
 * width as throughput, and the violet lobe at a diffuse bounce (sampling-lobe.ts).
 */
export function pathKey(paths: boolean): TemplateResult | typeof nothing {
  if (!paths) return nothing;
  const entries: [mark: string, name: string, detail: string, hint: string][] = [
    ['solid', msg('Solid'), msg('the path’s bounces'), msg('The path’s own rays: from the camera, bounce by bounce.')],
    [
      'dashed',
      msg('Dashed'),
      msg('shadow ray to a light'),
      msg('At a diffuse bounce, a shadow ray to each point or spot light, and with Light sampling on to a random point on each area light.'),
    ],
    ['widths', msg('Width'), msg('throughput so far'), msg('Thin: little of the light the path finds from here on reaches the pixel.')],
    [
      'lobe',
      msg('Violet lobe'),
      msg('density of the new direction'),
      msg('At a diffuse bounce: how likely each new direction is, a cosine lobe or a uniform hemisphere, as Bounce direction says.'),
    ],
  ];
  return html`<ul class="path-key" data-key="paths" aria-label=${msg('A pixel’s paths')}>
    ${entries.map(
      ([mark, name, detail, hint]) =>
        html`<li title=${hint}>
          <span class="path-mark ${mark}" aria-hidden="true"></span>
          <span>${name}<span class="detail"><span class="visually-hidden"> — </span>${detail}</span></span>
        </li>`,
    )}
  </ul>`;
}

export const pathKeyStyles = css`
  ul.path-key {
    display: grid;
    grid-template-columns: 1fr;
    gap: 2px;
    margin-top: 6px;
    font-size: 0.85em;
    color: var(--rt-muted);
  }
  .path-mark {
    flex: none;
    width: 44px;
    height: 6px;
    border-radius: 3px;
    background: var(--rt-text);
  }
  .path-mark.dashed {
    background: repeating-linear-gradient(90deg, var(--rt-text) 0 9px, transparent 9px 15px);
  }
  .path-mark.widths {
    height: 10px;
    clip-path: polygon(0 35%, 100% 0, 100% 100%, 0 65%);
  }
  .path-mark.lobe {
    height: 16px;
    border-radius: 22px 22px 0 0;
    background: rgba(160, 112, 255, 0.35);
    box-shadow: inset 0 0 0 1px #a070ff;
  }
`;
