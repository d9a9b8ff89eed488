  // page/rich-text.js: text with inline math between dollar signs, typeset by KaTeX (setRichText).
  // Text with inline math between dollar signs, typeset ("\$" is a dollar).
  function setRichText(element, text) {
    element.textContent = '';
    const parts = text.split(/(?<!\\)\$/);
    parts.forEach((part, k) => {
      if (k % 2 === 0) {
        element.append(part.replace(/\\\$/g, '$'));
      } else {
        const math = document.createElement('span');
        try {
          katex.render(part, math, { throwOnError: true });
        } catch (error) {
          math.textContent = part;
        }
        element.appendChild(math);
      }
    });
  }

