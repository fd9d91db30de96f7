/**
 * An XML well-formedness check for exported files (SVG), through jsdom's DOMParser. jsdom ships no
 * type declarations; the one constructor used here is typed by hand.
 */
// @ts-expect-error jsdom has no bundled types and @types/jsdom is not a dependency.
import { JSDOM as UntypedJsdom } from 'jsdom';

const JSDOM = UntypedJsdom as new (html: string) => { window: { DOMParser: typeof DOMParser } };

/** Parses `text` as `type`; throws with the parser's message when it is not well-formed. */
export function parseXml(text: string, type: DOMParserSupportedType = 'image/svg+xml'): Document {
  const doc = new new JSDOM('').window.DOMParser().parseFromString(text, type);
  const error = doc.getElementsByTagName('parsererror')[0];
  if (error) throw new Error(`not well-formed XML: ${error.textContent}`);
  return doc;
}
