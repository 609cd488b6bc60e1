// The message catalogues' virtual modules (scripts/messagesPlugin.js), for the modules that are
// type-checked (// @ts-check): one namespace's compiled messages, key → function of its arguments.
declare module 'virtual:messages/en/*' {
  const messages: Record<string, (args?: Record<string, unknown>) => string>;
  export default messages;
}
