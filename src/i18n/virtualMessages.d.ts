// The message catalogues' virtual modules (scripts/messagesPlugin.js), for the modules that are
// type-checked (// @ts-check): one namespace's compiled messages, key → function of its arguments.
declare module 'virtual:messages/en/*' {
  const messages: Record<string, (args?: Record<string, unknown>) => string>;
  export default messages;
}

// Every other language's whole catalogue, loaded when chosen: { lang: () => import(…) }.
declare module 'virtual:messages/languages' {
  const loaders: Record<string, () => Promise<{ default: Record<string, Record<string, (args?: Record<string, unknown>) => string>> }>>;
  export default loaders;
}

// Some namespaces of every other language, in one module: { lang: { namespace: messages } }.
declare module 'virtual:messages/every/*' {
  const catalogues: Record<string, Record<string, Record<string, (args?: Record<string, unknown>) => string>>>;
  export default catalogues;
}
