// The app's entry point: registers the elements; they do the rest when they connect.
import './util/zod-jitless.ts';
import './ui/shell/rt-app.ts';
