// The app's entry point: zod is told not to probe for eval first (the page's CSP forbids it),
// then the language and the level texts in it (so the first render is already in it), then
// the elements, which do the
// rest when they connect. The later modules are imported dynamically so that none of them
// runs, and parses, before that first line has.
import './util/zod-jitless.ts';

const { startLocale } = await import('./i18n/locale.ts');
const [{ loadLevelTexts }, locale] = await Promise.all([import('./app/level-catalog-browser.ts'), startLocale()]);
await loadLevelTexts(locale);
await import('./ui/shell/rt-app.ts');
// Dutch asked for and not loadable: the page is in English and says so (the module came with rt-app).
(await import('./ui/controls/locale-problem.ts')).showLocaleProblem(document);

// The offline copy (the service worker storing every file of the build) starts once the
// page has loaded, so that it does not compete with the first screen; the Menu says how it went.
// In a tab of a build the server no longer has, its module may be gone: that tab then keeps
// no copy of its own (the new build's pages store theirs), and nothing else breaks.
try {
  const { offlineCopy } = await import('./app/offline-copy.ts');
  const storeOfflineCopy = () => void offlineCopy.start({ protocol: location.protocol, serviceWorker: navigator.serviceWorker });
  if (document.readyState === 'complete') storeOfflineCopy();
  else addEventListener('load', storeOfflineCopy, { once: true });
} catch (error) {
  console.warn('The offline copy could not start: this page is of an older build', error);
}
