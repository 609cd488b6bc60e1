// The one width below which the lab lays itself out for a phone: controls folded, two views that
// sat side by side stacked (the CSS of those rules uses the same 599.98px).
export const PHONE_QUERY = '(max-width: 599.98px)';

/** The page's (or the frame's) media query for a phone: .matches now, and a 'change' event. */
export const phoneWidth = () => window.matchMedia(PHONE_QUERY);
