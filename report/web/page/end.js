  // page/end.js: the script closes.
})();
