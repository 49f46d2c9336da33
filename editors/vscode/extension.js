// Starts `kiln lsp` for .shader, .compute, .wgsl, .mat and kiln.toml files. The code lens above
// each pass (its active variant) runs the server's `kiln.nextVariant` command directly.
const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

let client;

function start() {
  const config = vscode.workspace.getConfiguration('kiln');
  const args = ['lsp'];
  const cacheDir = config.get('cacheDir');
  if (cacheDir) args.push('--cache-dir', cacheDir);
  client = new LanguageClient(
    'kiln',
    'kiln',
    { command: config.get('path') || 'kiln', args },
    {
      documentSelector: [
        { scheme: 'file', language: 'kiln-shaderlab' },
        { scheme: 'file', language: 'wgsl' },
        { scheme: 'file', pattern: '**/*.mat' },
        { scheme: 'file', pattern: '**/kiln.toml' },
      ],
    },
  );
  return client.start();
}

function activate(context) {
  context.subscriptions.push(
    vscode.commands.registerCommand('kiln.restart', async () => {
      if (client) await client.stop();
      await start();
    }),
  );
  return start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
