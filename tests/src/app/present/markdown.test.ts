import { createElement } from 'react';
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { Markdown } from '../../../../src/app/present/markdown.tsx';

const html = (text: string) => renderToStaticMarkup(createElement(Markdown, { text }));

describe('presentation Markdown subset', () => {
  it('renders paragraphs, line breaks, lists, bold, italic, code and http(s) links', () => {
    expect(html('Three **mirrors** meet at *π/3*.\nSee `k = 3`.\n\n- one\n- _two_')).toBe(
      '<div><p>Three <strong>mirrors</strong> meet at <em>π/3</em>.<br/>See <code>k = 3</code>.</p>' +
        '<ul><li>one</li><li><em>two</em></li></ul></div>',
    );
    expect(html('[paper](https://example.org/iis)')).toBe(
      '<div><p><a href="https://example.org/iis" target="_blank" rel="noopener noreferrer">paper</a></p></div>',
    );
  });

  it('never produces HTML from the text: tags, javascript: links stay literal, images are not loaded', () => {
    const out = html(
      '<script>alert(1)</script> <img src=x onerror=alert(1)> [x](javascript:alert(1)) ![i](http://a/b.png)',
    );
    expect(out).not.toContain('<script');
    expect(out).not.toContain('<img');
    expect(out).not.toContain('href="javascript');
    expect(out).toContain('&lt;script&gt;alert(1)&lt;/script&gt;');
    expect(out).toContain('[x](javascript:alert(1))');
  });

  it('leaves unmatched markers as text and ignores empty input', () => {
    expect(html('2 * 3 = 6 and a_b')).toBe('<div><p>2 * 3 = 6 and a_b</p></div>');
    expect(html('  \n\n ')).toBe('<div></div>');
  });
});
