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
  return html`<ul class="path-key" data-key="paths" aria-label=${msg('A pixel’s paths')}>
    <li><span class="path-mark solid" aria-hidden="true"></span>${msg('Solid: the path’s own rays, from the camera bounce by bounce')}</li>
    <li><span class="path-mark dashed" aria-hidden="true"></span>${msg('Dashed: a shadow ray to a point on a light (Light sampling)')}</li>
    <li><span class="path-mark widths" aria-hidden="true"></span>${msg('Width: the path’s throughput so far (thin: little of the light it finds reaches the pixel)')}</li>
    <li><span class="path-mark lobe" aria-hidden="true"></span>${msg('Violet lobe: at a diffuse bounce, how likely each new direction is (cosine lobe or uniform hemisphere, as Bounce direction says)')}</li>
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
  ul.path-key li {
    cursor: default;
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
