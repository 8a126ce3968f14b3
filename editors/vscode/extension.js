// Starts `vams lsp` for VHDL-AMS files and connects VS Code to it over standard input and
// output. Everything else (diagnostics, hover, definitions, references, symbols, completion,
// the "run testbench" lens) is the server's.
'use strict';

const vscode = require('vscode');
const { LanguageClient, TransportKind } = require('vscode-languageclient/node');

let client;

function activate(context) {
  const config = vscode.workspace.getConfiguration('vams');
  const command = config.get('path', 'vams');
  const debounce = String(config.get('debounce', 150));
  const server = {
    command,
    args: ['lsp', '--debounce', debounce],
    transport: TransportKind.stdio,
  };
  client = new LanguageClient(
    'vams',
    'vams language server',
    { run: server, debug: server },
    { documentSelector: [{ scheme: 'file', language: 'vhdl-ams' }, { scheme: 'untitled', language: 'vhdl-ams' }] },
  );
  context.subscriptions.push({ dispose: () => client && client.stop() });
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
