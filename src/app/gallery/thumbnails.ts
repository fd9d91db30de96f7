/**
 * The gallery's thumbnails: examples/thumbs/NAME.png, rendered by the CLI's CPU interpreter
 * (`npm run render-examples -- --thumbnails`), bundled as asset URLs.
 */
const urls = import.meta.glob('../../../examples/thumbs/*.png', {
  eager: true,
  query: '?url',
  import: 'default',
}) as Record<string, string>;

const byId = new Map(
  Object.entries(urls).map(([path, url]) => [path.replace(/^.*\//, '').replace(/\.png$/, ''), url]),
);

/** The thumbnail's URL for an example id, if there is one. */
export const thumbnailUrl = (id: string): string | undefined => byId.get(id);
