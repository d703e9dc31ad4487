<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
    <context>
        <name>Fatek::ConnectionDialog</name>
        <message>
            <source>New Connection</source>
            <translation>New Connection</translation>
        </message>
        <message>
            <source>(new)</source>
            <translation>(new)</translation>
        </message>
        <message>
            <source>%1 — %2</source>
            <translation>%1 — %2</translation>
        </message>
        <message>
            <source>e.g. Pump station</source>
            <translation>e.g. Pump station</translation>
        </message>
        <message>
            <source>Serial (RS-232 / RS-485)</source>
            <translation>Serial (RS-232 / RS-485)</translation>
        </message>
        <message>
            <source>TCP</source>
            <translation>TCP</translation>
        </message>
        <message>
            <source>UDP</source>
            <translation>UDP</translation>
        </message>
        <message>
            <source>Refresh</source>
            <translation>Refresh</translation>
        </message>
        <message>
            <source>&amp;Port:</source>
            <translation>&amp;Port:</translation>
        </message>
        <message>
            <source>&amp;Baud rate:</source>
            <translation>&amp;Baud rate:</translation>
        </message>
        <message>
            <source>&amp;Data bits:</source>
            <translation>&amp;Data bits:</translation>
        </message>
        <message>
            <source>None</source>
            <translation>None</translation>
        </message>
        <message>
            <source>Even</source>
            <translation>Even</translation>
        </message>
        <message>
            <source>Odd</source>
            <translation>Odd</translation>
        </message>
        <message>
            <source>Pa&amp;rity:</source>
            <translation>Pa&amp;rity:</translation>
        </message>
        <message>
            <source>&amp;Stop bits:</source>
            <translation>&amp;Stop bits:</translation>
        </message>
        <message>
            <source>Hardware (RTS/CTS)</source>
            <translation>Hardware (RTS/CTS)</translation>
        </message>
        <message>
            <source>Software (XON/XOFF)</source>
            <translation>Software (XON/XOFF)</translation>
        </message>
        <message>
            <source>&amp;Flow control:</source>
            <translation>&amp;Flow control:</translation>
        </message>
        <message>
            <source>&amp;Host:</source>
            <translation>&amp;Host:</translation>
        </message>
        <message>
            <source>Po&amp;rt:</source>
            <translation>Po&amp;rt:</translation>
        </message>
        <message>
            <source>FACON (ASCII)</source>
            <translation>FACON (ASCII)</translation>
        </message>
        <message>
            <source>Binary</source>
            <translation>Binary</translation>
        </message>
        <message>
            <source>Auto-detect</source>
            <translation>Auto-detect</translation>
        </message>
        <message>
            <source> ms</source>
            <translation> ms</translation>
        </message>
        <message>
            <source>Re&amp;cent:</source>
            <translation>Re&amp;cent:</translation>
        </message>
        <message>
            <source>&amp;Name:</source>
            <translation>&amp;Name:</translation>
        </message>
        <message>
            <source>&amp;Link:</source>
            <translation>&amp;Link:</translation>
        </message>
        <message>
            <source>&amp;URL:</source>
            <translation>&amp;URL:</translation>
        </message>
        <message>
            <source>The link as fatek-cli --link takes it (tcp://HOST:PORT, udp://…, serial:///dev/ttyUSB0?baud=19200&amp;format=7E1): type or paste one to fill the fields; it follows them.</source>
            <translation>The link as fatek-cli --link takes it (tcp://HOST:PORT, udp://…, serial:///dev/ttyUSB0?baud=19200&amp;format=7E1): type or paste one to fill the fields; it follows them.</translation>
        </message>
        <message>
            <source>Pro&amp;tocol:</source>
            <translation>Pro&amp;tocol:</translation>
        </message>
        <message>
            <source>St&amp;ation:</source>
            <translation>St&amp;ation:</translation>
        </message>
        <message>
            <source>T&amp;imeout:</source>
            <translation>T&amp;imeout:</translation>
        </message>
        <message>
            <source>R&amp;etries:</source>
            <translation>R&amp;etries:</translation>
        </message>
        <message>
            <source>C&amp;onnect</source>
            <translation>C&amp;onnect</translation>
        </message>
        <message>
            <source>PLC</source>
            <translation>PLC</translation>
        </message>
        <message>
            <source>Give the connection a name.</source>
            <translation>Give the connection a name.</translation>
        </message>
        <message>
            <source>The baud rate must be a positive number.</source>
            <translation>The baud rate must be a positive number.</translation>
        </message>
        <message>
            <source>MQTT gateway</source>
            <translation>MQTT gateway</translation>
        </message>
        <message>
            <source>mqtt://host:port, or mqtts://host:port for TLS</source>
            <translation>mqtt://host:port, or mqtts://host:port for TLS</translation>
        </message>
        <message>
            <source>&amp;Broker:</source>
            <translation>&amp;Broker:</translation>
        </message>
        <message>
            <source>Topic &amp;prefix:</source>
            <translation>Topic &amp;prefix:</translation>
        </message>
        <message>
            <source>e.g. line1</source>
            <translation>e.g. line1</translation>
        </message>
        <message>
            <source>The connection&apos;s name in the gateway&apos;s configuration</source>
            <translation>The connection&apos;s name in the gateway&apos;s configuration</translation>
        </message>
        <message>
            <source>&amp;Gateway connection:</source>
            <translation>&amp;Gateway connection:</translation>
        </message>
        <message>
            <source>optional</source>
            <translation>optional</translation>
        </message>
        <message>
            <source>&amp;User:</source>
            <translation>&amp;User:</translation>
        </message>
        <message>
            <source>optional; not saved</source>
            <translation>optional; not saved</translation>
        </message>
        <message>
            <source>Pass&amp;word:</source>
            <translation>Pass&amp;word:</translation>
        </message>
        <message>
            <source>optional; mqtts:// only</source>
            <translation>optional; mqtts:// only</translation>
        </message>
        <message>
            <source>Browse…</source>
            <translation>Browse…</translation>
        </message>
        <message>
            <source>TLS CA &amp;file:</source>
            <translation>TLS CA &amp;file:</translation>
        </message>
        <message>
            <source>CA Certificate</source>
            <translation>CA Certificate</translation>
        </message>
        <message>
            <source>Certificates (*.crt *.pem);;All files (*)</source>
            <translation>Certificates (*.crt *.pem);;All files (*)</translation>
        </message>
        <message>
            <source>Client c&amp;ertificate:</source>
            <translation>Client c&amp;ertificate:</translation>
        </message>
        <message>
            <source>Client Certificate</source>
            <translation>Client Certificate</translation>
        </message>
        <message>
            <source>Client &amp;key:</source>
            <translation>Client &amp;key:</translation>
        </message>
        <message>
            <source>with the client certificate</source>
            <translation>with the client certificate</translation>
        </message>
        <message>
            <source>Client Key</source>
            <translation>Client Key</translation>
        </message>
        <message>
            <source>Keys (*.key *.pem);;All files (*)</source>
            <translation>Keys (*.key *.pem);;All files (*)</translation>
        </message>
        <message>
            <source>TLS files need an mqtts:// broker URL.</source>
            <translation>TLS files need an mqtts:// broker URL.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ConnectionListModel</name>
        <message>
            <source>Round trip: last %1 ms, median %2 ms, 99% %3 ms</source>
            <translation>Round trip: last %1 ms, median %2 ms, 99% %3 ms</translation>
        </message>
        <message>
            <source>Station the tools act on; double-click to change</source>
            <translation>Station the tools act on; double-click to change</translation>
        </message>
        <message>
            <source>Station %1: %2 requests, %3 errors, RTT %4 ms</source>
            <translation>Station %1: %2 requests, %3 errors, RTT %4 ms</translation>
        </message>
        <message>
            <source>URL: %1</source>
            <translation>URL: %1</translation>
        </message>
        <message>
            <source>; not answering, polled again at %1</source>
            <translation>; not answering, polled again at %1</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>Name</translation>
        </message>
        <message>
            <source>Link</source>
            <translation>Link</translation>
        </message>
        <message>
            <source>Station</source>
            <translation>Station</translation>
        </message>
        <message>
            <source>State</source>
            <translation>State</translation>
        </message>
        <message>
            <source>Req/s</source>
            <translation>Req/s</translation>
        </message>
        <message>
            <source>Errors</source>
            <translation>Errors</translation>
        </message>
        <message>
            <source>RTT</source>
            <translation>RTT</translation>
        </message>
        <message>
            <source>%1 timeouts, %2 checksum errors, %3 PLC errors, %4 retries, %5 link failures</source>
            <translation>%1 timeouts, %2 checksum errors, %3 PLC errors, %4 retries, %5 link failures</translation>
        </message>
        <message>
            <source>Station %1: %2 (RUN/STOP read every %3 s)</source>
            <translation>Station %1: %2 (RUN/STOP read every %3 s)</translation>
        </message>
        <message>
            <source>The PLC has not said what it is yet</source>
            <translation>The PLC has not said what it is yet</translation>
        </message>
        <message>
            <source>PLC</source>
            <translation>PLC</translation>
        </message>
    </context>
    <context>
        <name>Fatek::HistoryCenter</name>
        <message>
            <source>History: %1</source>
            <translation>History: %1</translation>
        </message>
        <message>
            <source>History: %1 is written again.</source>
            <translation>History: %1 is written again.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::HistorySettingsDialog</name>
        <message numerus="yes">
            <source>History Settings (%n row(s))</source>
            <translation>
                <numerusform>History Settings (%n row)</numerusform>
                <numerusform>History Settings (%n rows)</numerusform>
            </translation>
        </message>
        <message>
            <source>Bits and texts keep every change</source>
            <translation>Bits and texts keep every change</translation>
        </message>
        <message>
            <source>A change smaller than this from the last value kept is not recorded; 0: every change</source>
            <translation>A change smaller than this from the last value kept is not recorded; 0: every change</translation>
        </message>
        <message>
            <source> s</source>
            <translation> s</translation>
        </message>
        <message>
            <source>A value is recorded at least this often, changed or not, so that a flat line is known to be flat</source>
            <translation>A value is recorded at least this often, changed or not, so that a flat line is known to be flat</translation>
        </message>
        <message>
            <source>&amp;Deadband:</source>
            <translation>&amp;Deadband:</translation>
        </message>
        <message>
            <source>&amp;Heartbeat:</source>
            <translation>&amp;Heartbeat:</translation>
        </message>
        <message>
            <source>Recorded: the first value, every change beyond the deadband, every change of quality, and the value once per heartbeat.</source>
            <translation>Recorded: the first value, every change beyond the deadband, every change of quality, and the value once per heartbeat.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::HistoryUi</name>
        <message>
            <source>Record in &amp;History</source>
            <translation>Record in &amp;History</translation>
        </message>
        <message>
            <source>Keep the values of the selected rows in the history, to look back at them in the trend (not in operator mode)</source>
            <translation>Keep the values of the selected rows in the history, to look back at them in the trend (not in operator mode)</translation>
        </message>
        <message>
            <source>History &amp;Settings…</source>
            <translation>History &amp;Settings…</translation>
        </message>
        <message>
            <source>Deadband and heartbeat of the selected rows&apos; recording</source>
            <translation>Deadband and heartbeat of the selected rows&apos; recording</translation>
        </message>
        <message>
            <source>Operator mode: what is recorded in the history cannot be changed.</source>
            <translation>Operator mode: what is recorded in the history cannot be changed.</translation>
        </message>
        <message>
            <source>Select the rows to record in the history.</source>
            <translation>Select the rows to record in the history.</translation>
        </message>
        <message numerus="yes">
            <source>%n row(s) recorded in the history (%1).</source>
            <translation>
                <numerusform>%n row recorded in the history (%1).</numerusform>
                <numerusform>%n rows recorded in the history (%1).</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n row(s) no longer recorded in the history.</source>
            <translation>
                <numerusform>%n row no longer recorded in the history.</numerusform>
                <numerusform>%n rows no longer recorded in the history.</numerusform>
            </translation>
        </message>
        <message>
            <source>Select the rows whose recording to set.</source>
            <translation>Select the rows whose recording to set.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::Message</name>
        <message>
            <source>Outcome unknown: %1 It may have been carried out; reading it back as soon as the PLC answers.</source>
            <translation>Outcome unknown: %1 It may have been carried out; reading it back as soon as the PLC answers.</translation>
        </message>
        <message>
            <source>Done: confirmed by reading it back.</source>
            <translation>Done: confirmed by reading it back.</translation>
        </message>
        <message>
            <source>Not done: read back afterwards, the PLC does not hold what was sent (not carried out, or changed since by its program).</source>
            <translation>Not done: read back afterwards, the PLC does not hold what was sent (not carried out, or changed since by its program).</translation>
        </message>
        <message>
            <source>Outcome still unknown: it could not be read back (%1). Check the PLC.</source>
            <translation>Outcome still unknown: it could not be read back (%1). Check the PLC.</translation>
        </message>
        <message>
            <source>other queries to the PLC kept going unanswered meanwhile, so an answer could not be told apart from a late one</source>
            <translation>other queries to the PLC kept going unanswered meanwhile, so an answer could not be told apart from a late one</translation>
        </message>
        <message>
            <source>Outcome unknown: no read can tell whether it was carried out. Check the PLC.</source>
            <translation>Outcome unknown: no read can tell whether it was carried out. Check the PLC.</translation>
        </message>
        <message>
            <source>Stopped at the write of %1: %2</source>
            <translation>Stopped at the write of %1: %2</translation>
        </message>
        <message>
            <source>Not sent: it waited past its deadline (nothing reached the PLC).</source>
            <translation>Not sent: it waited past its deadline (nothing reached the PLC).</translation>
        </message>
        <message>
            <source>Outcome unknown: %1 went to the gateway and no final reply came (%2); it may have been carried out.</source>
            <translation>Outcome unknown: %1 went to the gateway and no final reply came (%2); it may have been carried out.</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>%1; %2</source>
            <translation>%1; %2</translation>
        </message>
        <message>
            <source>no error</source>
            <translation>no error</translation>
        </message>
        <message>
            <source>illegal value</source>
            <translation>illegal value</translation>
        </message>
        <message>
            <source>write prohibited (ROM pack)</source>
            <translation>write prohibited (ROM pack)</translation>
        </message>
        <message>
            <source>illegal format, or command cannot execute</source>
            <translation>illegal format, or command cannot execute</translation>
        </message>
        <message>
            <source>cannot RUN: ladder checksum error</source>
            <translation>cannot RUN: ladder checksum error</translation>
        </message>
        <message>
            <source>cannot RUN: PLC ID differs from ladder ID</source>
            <translation>cannot RUN: PLC ID differs from ladder ID</translation>
        </message>
        <message>
            <source>cannot RUN: syntax check error</source>
            <translation>cannot RUN: syntax check error</translation>
        </message>
        <message>
            <source>cannot RUN: function not supported</source>
            <translation>cannot RUN: function not supported</translation>
        </message>
        <message>
            <source>illegal address</source>
            <translation>illegal address</translation>
        </message>
        <message>
            <source>unknown error code</source>
            <translation>unknown error code</translation>
        </message>
        <message>
            <source>PLC error %1: %2</source>
            <translation>PLC error %1: %2</translation>
        </message>
        <message>
            <source>PLC error %1: %2 %3</source>
            <translation>PLC error %1: %2 %3</translation>
        </message>
        <message>
            <source>read brief status</source>
            <translation>read brief status</translation>
        </message>
        <message>
            <source>RUN/STOP control</source>
            <translation>RUN/STOP control</translation>
        </message>
        <message>
            <source>single discrete control</source>
            <translation>single discrete control</translation>
        </message>
        <message>
            <source>read enable/disable flags</source>
            <translation>read enable/disable flags</translation>
        </message>
        <message>
            <source>read consecutive discretes</source>
            <translation>read consecutive discretes</translation>
        </message>
        <message>
            <source>write consecutive discretes</source>
            <translation>write consecutive discretes</translation>
        </message>
        <message>
            <source>read consecutive registers</source>
            <translation>read consecutive registers</translation>
        </message>
        <message>
            <source>write consecutive registers</source>
            <translation>write consecutive registers</translation>
        </message>
        <message>
            <source>mixed read</source>
            <translation>mixed read</translation>
        </message>
        <message>
            <source>mixed write</source>
            <translation>mixed write</translation>
        </message>
        <message>
            <source>loopback test</source>
            <translation>loopback test</translation>
        </message>
        <message>
            <source>read program page</source>
            <translation>read program page</translation>
        </message>
        <message>
            <source>write program page</source>
            <translation>write program page</translation>
        </message>
        <message>
            <source>read detail status</source>
            <translation>read detail status</translation>
        </message>
        <message>
            <source>unknown command</source>
            <translation>unknown command</translation>
        </message>
        <message>
            <source>station %1, %2 %3</source>
            <translation>station %1, %2 %3</translation>
        </message>
        <message>
            <source>invalid FACON frame (%1 bytes): %2</source>
            <translation>invalid FACON frame (%1 bytes): %2</translation>
        </message>
        <message>
            <source>bad binary frame (%1 bytes): %2</source>
            <translation>bad binary frame (%1 bytes): %2</translation>
        </message>
        <message>
            <source>answer: OK</source>
            <translation>answer: OK</translation>
        </message>
        <message>
            <source>answer: OK, %1 data chars &quot;%2&quot;</source>
            <translation>answer: OK, %1 data chars &quot;%2&quot;</translation>
        </message>
        <message>
            <source>answer: OK, %1 data bytes: %2</source>
            <translation>answer: OK, %1 data bytes: %2</translation>
        </message>
        <message>
            <source>answer: no error digit</source>
            <translation>answer: no error digit</translation>
        </message>
        <message>
            <source>answer: no error byte</source>
            <translation>answer: no error byte</translation>
        </message>
        <message>
            <source>answer: malformed &quot;%1&quot;</source>
            <translation>answer: malformed &quot;%1&quot;</translation>
        </message>
        <message>
            <source>answer: echo of %1 bytes</source>
            <translation>answer: echo of %1 bytes</translation>
        </message>
        <message>
            <source>answer: error %1 (%2)</source>
            <translation>answer: error %1 (%2)</translation>
        </message>
        <message>
            <source>unknown command, data &quot;%1&quot;</source>
            <translation>unknown command, data &quot;%1&quot;</translation>
        </message>
        <message>
            <source>%1 chars &quot;%2&quot;</source>
            <translation>%1 chars &quot;%2&quot;</translation>
        </message>
        <message>
            <source>STOP, or answer: no error</source>
            <translation>STOP, or answer: no error</translation>
        </message>
        <message>
            <source>%1 elements%2</source>
            <translation>%1 elements%2</translation>
        </message>
        <message>
            <source>page %1</source>
            <translation>page %1</translation>
        </message>
        <message>
            <source>page %1, 64 words</source>
            <translation>page %1, 64 words</translation>
        </message>
        <message>
            <source>disable %1</source>
            <translation>disable %1</translation>
        </message>
        <message>
            <source>enable %1</source>
            <translation>enable %1</translation>
        </message>
        <message>
            <source>set %1</source>
            <translation>set %1</translation>
        </message>
        <message>
            <source>reset %1</source>
            <translation>reset %1</translation>
        </message>
        <message>
            <source>link lost</source>
            <translation>link lost</translation>
        </message>
        <message>
            <source>stale bytes discarded</source>
            <translation>stale bytes discarded</translation>
        </message>
        <message>
            <source>received outside an answer</source>
            <translation>received outside an answer</translation>
        </message>
        <message>
            <source>unexpected bytes</source>
            <translation>unexpected bytes</translation>
        </message>
        <message>
            <source>no query pending</source>
            <translation>no query pending</translation>
        </message>
        <message>
            <source>echo of the query</source>
            <translation>echo of the query</translation>
        </message>
        <message>
            <source>raw answer</source>
            <translation>raw answer</translation>
        </message>
        <message>
            <source>raw frame</source>
            <translation>raw frame</translation>
        </message>
        <message>
            <source>no complete frame</source>
            <translation>no complete frame</translation>
        </message>
        <message>
            <source>more than %1 bytes: rest not read</source>
            <translation>more than %1 bytes: rest not read</translation>
        </message>
        <message>
            <source>no answer within %1 ms</source>
            <translation>no answer within %1 ms</translation>
        </message>
        <message>
            <source>protocol detected: %1</source>
            <translation>protocol detected: %1</translation>
        </message>
        <message>
            <source>%1 bytes, first %2 kept</source>
            <translation>%1 bytes, first %2 kept</translation>
        </message>
        <message>
            <source>closing</source>
            <translation>closing</translation>
        </message>
        <message>
            <source>sending %1 queued write(s) first, at most %2 ms</source>
            <translation>sending %1 queued write(s) first, at most %2 ms</translation>
        </message>
        <message>
            <source>closed</source>
            <translation>closed</translation>
        </message>
        <message>
            <source>connecting</source>
            <translation>connecting</translation>
        </message>
        <message>
            <source>connected</source>
            <translation>connected</translation>
        </message>
        <message>
            <source>lost</source>
            <translation>lost</translation>
        </message>
        <message>
            <source>reconnecting</source>
            <translation>reconnecting</translation>
        </message>
        <message>
            <source>link lost: %1</source>
            <translation>link lost: %1</translation>
        </message>
        <message>
            <source>%1; next attempt in %2 s</source>
            <translation>%1; next attempt in %2 s</translation>
        </message>
        <message>
            <source>the session was closed</source>
            <translation>the session was closed</translation>
        </message>
        <message>
            <source>the session was closed after waiting %1 ms for queued writes</source>
            <translation>the session was closed after waiting %1 ms for queued writes</translation>
        </message>
        <message>
            <source>%1 does not take data</source>
            <translation>%1 does not take data</translation>
        </message>
        <message>
            <source>no connection to %1 within %2 ms</source>
            <translation>no connection to %1 within %2 ms</translation>
        </message>
        <message>
            <source>%1 closed the connection</source>
            <translation>%1 closed the connection</translation>
        </message>
        <message>
            <source>cannot open %1: %2</source>
            <translation>cannot open %1: %2</translation>
        </message>
        <message>
            <source>Protocol auto-detect: station %1 answered neither in FACON nor in binary (%2)</source>
            <translation>Protocol auto-detect: station %1 answered neither in FACON nor in binary (%2)</translation>
        </message>
        <message>
            <source>Not sent: a broadcast (station 0) has no station to detect the protocol with; give --protocol for a broadcast (or choose FACON or binary in the connection)</source>
            <translation>Not sent: a broadcast (station 0) has no station to detect the protocol with; give --protocol for a broadcast (or choose FACON or binary in the connection)</translation>
        </message>
        <message>
            <source>No answer from station %1 within %2 ms (attempt %3 of %4).</source>
            <translation>No answer from station %1 within %2 ms (attempt %3 of %4).</translation>
        </message>
        <message>
            <source>No answer within %1 ms.</source>
            <translation>No answer within %1 ms.</translation>
        </message>
        <message>
            <source>Not sent: the link is not open.</source>
            <translation>Not sent: the link is not open.</translation>
        </message>
        <message>
            <source>Not sent: the link is down (%1).</source>
            <translation>Not sent: the link is down (%1).</translation>
        </message>
        <message>
            <source>Not sent: %1 requests are already waiting on this link (the PLC answers slower than requests arrive).</source>
            <translation>Not sent: %1 requests are already waiting on this link (the PLC answers slower than requests arrive).</translation>
        </message>
        <message>
            <source>Read-only mode: &quot;%1&quot; was not sent. Leave operator mode to change the PLC.</source>
            <translation>Read-only mode: &quot;%1&quot; was not sent. Leave operator mode to change the PLC.</translation>
        </message>
        <message>
            <source>Cancelled before it was sent.</source>
            <translation>Cancelled before it was sent.</translation>
        </message>
        <message>
            <source>Not sent: the link is closing.</source>
            <translation>Not sent: the link is closing.</translation>
        </message>
        <message>
            <source>Not sent: %1 did not take the frame within %2 ms (%3 of %4 bytes unsent).</source>
            <translation>Not sent: %1 did not take the frame within %2 ms (%3 of %4 bytes unsent).</translation>
        </message>
        <message>
            <source>The answer carries fewer values than asked.</source>
            <translation>The answer carries fewer values than asked.</translation>
        </message>
        <message>
            <source>Could not write to %1.</source>
            <translation>Could not write to %1.</translation>
        </message>
        <message>
            <source>not executed</source>
            <translation>not executed</translation>
        </message>
        <message>
            <source>Station %1 does not answer (%2 requests in a row); polled again at %3.</source>
            <translation>Station %1 does not answer (%2 requests in a row); polled again at %3.</translation>
        </message>
        <message>
            <source>Late: no new value for %1 s (polled every %2 ms); the line is busy or slow.</source>
            <translation>Late: no new value for %1 s (polled every %2 ms); the line is busy or slow.</translation>
        </message>
        <message>
            <source>station %1 demoted after %2 requests without an answer; next try at %3</source>
            <translation>station %1 demoted after %2 requests without an answer; next try at %3</translation>
        </message>
        <message>
            <source>station %1 answers again; polled as usual</source>
            <translation>station %1 answers again; polled as usual</translation>
        </message>
        <message>
            <source>station %1: items polled every %2 ms are read every %3 ms, as fast as the line allows; late is counted from that</source>
            <translation>station %1: items polled every %2 ms are read every %3 ms, as fast as the line allows; late is counted from that</translation>
        </message>
        <message>
            <source>station %1: items polled every %2 ms are read on time again</source>
            <translation>station %1: items polled every %2 ms are read on time again</translation>
        </message>
        <message>
            <source>Empty address: type an element such as R12 or X0.</source>
            <translation>Empty address: type an element such as R12 or X0.</translation>
        </message>
        <message>
            <source>Invalid address &quot;%1&quot;: it must start with an element type such as R, X or DWM.</source>
            <translation>Invalid address &quot;%1&quot;: it must start with an element type such as R, X or DWM.</translation>
        </message>
        <message>
            <source>Invalid address &quot;%1&quot;: unknown element type &quot;%2&quot; (known: %3).</source>
            <translation>Invalid address &quot;%1&quot;: unknown element type &quot;%2&quot; (known: %3).</translation>
        </message>
        <message>
            <source>Invalid address &quot;%1&quot;: the element number is missing (e.g. %2).</source>
            <translation>Invalid address &quot;%1&quot;: the element number is missing (e.g. %2).</translation>
        </message>
        <message>
            <source>Invalid address &quot;%1&quot;: &quot;%2&quot; is not a decimal element number.</source>
            <translation>Invalid address &quot;%1&quot;: &quot;%2&quot; is not a decimal element number.</translation>
        </message>
        <message>
            <source>Invalid address &quot;%1&quot;: element number too large.</source>
            <translation>Invalid address &quot;%1&quot;: element number too large.</translation>
        </message>
        <message>
            <source>Address %1 is out of range: %2 numbers go from 0 to %3.</source>
            <translation>Address %1 is out of range: %2 numbers go from 0 to %3.</translation>
        </message>
        <message>
            <source>Address %1 is not aligned: %2 must start at a multiple of %3 (e.g. %4).</source>
            <translation>Address %1 is not aligned: %2 must start at a multiple of %3 (e.g. %4).</translation>
        </message>
        <message>
            <source>%1 elements from %2 run past %3, the last %4.</source>
            <translation>%1 elements from %2 run past %3, the last %4.</translation>
        </message>
        <message>
            <source>Enter the PLC&apos;s IP address or host name.</source>
            <translation>Enter the PLC&apos;s IP address or host name.</translation>
        </message>
        <message>
            <source>Port 0 is not usable; FATEK Ethernet modules usually listen on 500.</source>
            <translation>Port 0 is not usable; FATEK Ethernet modules usually listen on 500.</translation>
        </message>
        <message>
            <source>Choose a serial port.</source>
            <translation>Choose a serial port.</translation>
        </message>
        <message>
            <source>Baud rate %1 is out of range (1200 to 921600).</source>
            <translation>Baud rate %1 is out of range (1200 to 921600).</translation>
        </message>
        <message>
            <source>Data bits must be 7 or 8, not %1.</source>
            <translation>Data bits must be 7 or 8, not %1.</translation>
        </message>
        <message>
            <source>Stop bits must be 1 or 2, not %1.</source>
            <translation>Stop bits must be 1 or 2, not %1.</translation>
        </message>
        <message>
            <source>Timeout %1 ms is out of range (1 to 60000 ms).</source>
            <translation>Timeout %1 ms is out of range (1 to 60000 ms).</translation>
        </message>
        <message>
            <source>Retries %1 is out of range (0 to 10).</source>
            <translation>Retries %1 is out of range (0 to 10).</translation>
        </message>
        <message>
            <source>Demote after %1 unanswered requests is out of range (0 to 100; 0 never demotes).</source>
            <translation>Demote after %1 unanswered requests is out of range (0 to 100; 0 never demotes).</translation>
        </message>
        <message>
            <source>A demotion of %1 ms is out of range (1000 to 600000 ms).</source>
            <translation>A demotion of %1 ms is out of range (1000 to 600000 ms).</translation>
        </message>
        <message>
            <source>Inter-frame silence %1 ms is out of range (0 to 1000 ms).</source>
            <translation>Inter-frame silence %1 ms is out of range (0 to 1000 ms).</translation>
        </message>
        <message>
            <source>Connect timeout must be at least 1 ms.</source>
            <translation>Connect timeout must be at least 1 ms.</translation>
        </message>
        <message>
            <source>Reconnect delays must be positive, the maximum not below the minimum.</source>
            <translation>Reconnect delays must be positive, the maximum not below the minimum.</translation>
        </message>
        <message>
            <source>No link given: write tcp://HOST[:PORT], udp://HOST[:PORT] or serial://PORT.</source>
            <translation>No link given: write tcp://HOST[:PORT], udp://HOST[:PORT] or serial://PORT.</translation>
        </message>
        <message>
            <source>Link &quot;%1&quot;: start it with tcp://, udp:// or serial:// (for example tcp://192.168.1.5:500 or serial:///dev/ttyUSB0).</source>
            <translation>Link &quot;%1&quot;: start it with tcp://, udp:// or serial:// (for example tcp://192.168.1.5:500 or serial:///dev/ttyUSB0).</translation>
        </message>
        <message>
            <source>Link &quot;%1&quot;: write HOST or HOST:PORT with a port from 1 to 65535; an IPv6 address goes in brackets, as in [fe80::1]:500.</source>
            <translation>Link &quot;%1&quot;: write HOST or HOST:PORT with a port from 1 to 65535; an IPv6 address goes in brackets, as in [fe80::1]:500.</translation>
        </message>
        <message>
            <source>Link &quot;%1&quot;: name the serial port, as in serial:///dev/ttyUSB0 or serial://COM3.</source>
            <translation>Link &quot;%1&quot;: name the serial port, as in serial:///dev/ttyUSB0 or serial://COM3.</translation>
        </message>
        <message>
            <source>Link &quot;%1&quot;: no setting &quot;%2&quot; (this link takes %3).</source>
            <translation>Link &quot;%1&quot;: no setting &quot;%2&quot; (this link takes %3).</translation>
        </message>
        <message>
            <source>Link &quot;%1&quot;: %2 takes %4, not &quot;%3&quot;.</source>
            <translation>Link &quot;%1&quot;: %2 takes %4, not &quot;%3&quot;.</translation>
        </message>
        <message>
            <source>Incomplete range &quot;%1&quot;: write it as first..last, e.g. R100..R163.</source>
            <translation>Incomplete range &quot;%1&quot;: write it as first..last, e.g. R100..R163.</translation>
        </message>
        <message>
            <source>Range &quot;%1&quot; mixes %2 and %3: both ends must be the same element type.</source>
            <translation>Range &quot;%1&quot; mixes %2 and %3: both ends must be the same element type.</translation>
        </message>
        <message>
            <source>Range &quot;%1&quot; runs backwards: write the lower address first (%2).</source>
            <translation>Range &quot;%1&quot; runs backwards: write the lower address first (%2).</translation>
        </message>
        <message>
            <source>Range &quot;%1&quot; does not end on a whole element: %2 elements are %3 apart (%4, %5, ...).</source>
            <translation>Range &quot;%1&quot; does not end on a whole element: %2 elements are %3 apart (%4, %5, ...).</translation>
        </message>
        <message>
            <source>Range &quot;%1&quot; has %2 elements; at most %3 fit in one range.</source>
            <translation>Range &quot;%1&quot; has %2 elements; at most %3 fit in one range.</translation>
        </message>
        <message>
            <source>No range given; write for example X0-255, Y0-255.</source>
            <translation>No range given; write for example X0-255, Y0-255.</translation>
        </message>
        <message>
            <source>“%1” is not a hex digit; type bytes like 01 46 03 52 00 0C.</source>
            <translation>“%1” is not a hex digit; type bytes like 01 46 03 52 00 0C.</translation>
        </message>
        <message>
            <source>Nothing to send: type the frame&apos;s bytes in hex.</source>
            <translation>Nothing to send: type the frame&apos;s bytes in hex.</translation>
        </message>
        <message>
            <source>Odd number of hex digits: each byte needs two (0C, not C).</source>
            <translation>Odd number of hex digits: each byte needs two (0C, not C).</translation>
        </message>
        <message>
            <source>Only printable ASCII can be typed; write control characters as &lt;STX&gt;, &lt;ETX&gt; or &lt;0D&gt;.</source>
            <translation>Only printable ASCII can be typed; write control characters as &lt;STX&gt;, &lt;ETX&gt; or &lt;0D&gt;.</translation>
        </message>
        <message>
            <source>Nothing to send: type the frame.</source>
            <translation>Nothing to send: type the frame.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a BCD number (digits 0-9 only)</source>
            <translation>&quot;%1&quot; is not a BCD number (digits 0-9 only)</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a hexadecimal number</source>
            <translation>&quot;%1&quot; is not a hexadecimal number</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a binary number (only 0 and 1)</source>
            <translation>&quot;%1&quot; is not a binary number (only 0 and 1)</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a number</source>
            <translation>&quot;%1&quot; is not a number</translation>
        </message>
        <message>
            <source>BCD values cannot be negative (&quot;%1&quot;)</source>
            <translation>BCD values cannot be negative (&quot;%1&quot;)</translation>
        </message>
        <message>
            <source>%1 does not fit %2 as BCD (0..%3)</source>
            <translation>%1 does not fit %2 as BCD (0..%3)</translation>
        </message>
        <message>
            <source>%1 does not fit %2 (%3)</source>
            <translation>%1 does not fit %2 (%3)</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a bit value: type ON, OFF, 1 or 0</source>
            <translation>&quot;%1&quot; is not a bit value: type ON, OFF, 1 or 0</translation>
        </message>
        <message>
            <source>%1 does not fit a 32-bit float (largest about ±%2)</source>
            <translation>%1 does not fit a 32-bit float (largest about ±%2)</translation>
        </message>
        <message>
            <source>%1 does not fit a 64-bit double (largest about ±%2)</source>
            <translation>%1 does not fit a 64-bit double (largest about ±%2)</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is too long: %2 holds %3 ASCII characters</source>
            <translation>&quot;%1&quot; is too long: %2 holds %3 ASCII characters</translation>
        </message>
        <message>
            <source>&quot;%1&quot; contains a character that is not plain printable ASCII (letters, digits, punctuation and space only)</source>
            <translation>&quot;%1&quot; contains a character that is not plain printable ASCII (letters, digits, punctuation and space only)</translation>
        </message>
        <message>
            <source>a bit</source>
            <translation>a bit</translation>
        </message>
        <message>
            <source>a 16-bit register</source>
            <translation>a 16-bit register</translation>
        </message>
        <message>
            <source>a %1-bit value</source>
            <translation>a %1-bit value</translation>
        </message>
        <message>
            <source>A %1-bit value cannot be written (only 1, 16, 32 or 64 bits).</source>
            <translation>A %1-bit value cannot be written (only 1, 16, 32 or 64 bits).</translation>
        </message>
        <message>
            <source>No value typed: type ON, OFF, 1 or 0.</source>
            <translation>No value typed: type ON, OFF, 1 or 0.</translation>
        </message>
        <message>
            <source>No value typed: type a number such as 12, -5, 0x1A or 1Ah.</source>
            <translation>No value typed: type a number such as 12, -5, 0x1A or 1Ah.</translation>
        </message>
        <message>
            <source>%1: %2 elements are not available in the FACON protocol (binary protocol only).</source>
            <translation>%1: %2 elements are not available in the FACON protocol (binary protocol only).</translation>
        </message>
        <message>
            <source>Value %1 for %2: a discrete takes 0 (OFF) or 1 (ON).</source>
            <translation>Value %1 for %2: a discrete takes 0 (OFF) or 1 (ON).</translation>
        </message>
        <message>
            <source>Value %1 for %2 does not fit a 16-bit register (0..65535).</source>
            <translation>Value %1 for %2 does not fit a 16-bit register (0..65535).</translation>
        </message>
        <message>
            <source>%1 needs a discrete (X Y M S T C), not %2.</source>
            <translation>%1 needs a discrete (X Y M S T C), not %2.</translation>
        </message>
        <message>
            <source>%1: %2 points requested; one request carries 1 to 256 points.</source>
            <translation>%1: %2 points requested; one request carries 1 to 256 points.</translation>
        </message>
        <message>
            <source>%1 needs a register (R, D, WY, DR, ...), not %2; use discretes commands for single points.</source>
            <translation>%1 needs a register (R, D, WY, DR, ...), not %2; use discretes commands for single points.</translation>
        </message>
        <message>
            <source>%1: %2 16-bit registers requested; one request carries 1 to %3.</source>
            <translation>%1: %2 16-bit registers requested; one request carries 1 to %3.</translation>
        </message>
        <message>
            <source>%1: %2 32-bit registers requested; one request carries 1 to %3 (32-bit registers count as two words).</source>
            <translation>%1: %2 32-bit registers requested; one request carries 1 to %3 (32-bit registers count as two words).</translation>
        </message>
        <message>
            <source>%1: no element given.</source>
            <translation>%1: no element given.</translation>
        </message>
        <message>
            <source>%1: %2 elements; at most %3 words fit in one request.</source>
            <translation>%1: %2 elements; at most %3 words fit in one request.</translation>
        </message>
        <message>
            <source>%1: %2 words requested; at most %3 fit in one request (a discrete or 16-bit element counts 1, a 32-bit element 2).</source>
            <translation>%1: %2 words requested; at most %3 fit in one request (a discrete or 16-bit element counts 1, a 32-bit element 2).</translation>
        </message>
        <message>
            <source>Station %1 is not valid: stations are 1 to 254 (0 = broadcast).</source>
            <translation>Station %1 is not valid: stations are 1 to 254 (0 = broadcast).</translation>
        </message>
        <message>
            <source>Unknown discrete operation %1.</source>
            <translation>Unknown discrete operation %1.</translation>
        </message>
        <message>
            <source>Mixed write: %1 addresses but %2 values.</source>
            <translation>Mixed write: %1 addresses but %2 values.</translation>
        </message>
        <message>
            <source>Loopback test data is %1 bytes; at most 256 fit in one request.</source>
            <translation>Loopback test data is %1 bytes; at most 256 fit in one request.</translation>
        </message>
        <message>
            <source>FACON loopback data must be printable ASCII characters.</source>
            <translation>FACON loopback data must be printable ASCII characters.</translation>
        </message>
        <message>
            <source>Program pages (4F/50) exist only in the FACON protocol.</source>
            <translation>Program pages (4F/50) exist only in the FACON protocol.</translation>
        </message>
        <message>
            <source>A program page holds exactly 64 words; %1 given.</source>
            <translation>A program page holds exactly 64 words; %1 given.</translation>
        </message>
        <message>
            <source>Program words are 16-bit (0..65535).</source>
            <translation>Program words are 16-bit (0..65535).</translation>
        </message>
        <message>
            <source>Unknown command code %1.</source>
            <translation>Unknown command code %1.</translation>
        </message>
        <message>
            <source>%1: station 0 is broadcast; PLCs do not answer it, so nothing can be read there.</source>
            <translation>%1: station 0 is broadcast; PLCs do not answer it, so nothing can be read there.</translation>
        </message>
        <message>
            <source>table %1</source>
            <translation>table %1</translation>
        </message>
        <message>
            <source>table %1, item %2</source>
            <translation>table %1, item %2</translation>
        </message>
        <message>
            <source>line %1</source>
            <translation>line %1</translation>
        </message>
        <message>
            <source>Not saved</source>
            <translation>Not saved</translation>
        </message>
        <message>
            <source>%1 items are more than one table holds (at most %2)</source>
            <translation>%1 items are more than one table holds (at most %2)</translation>
        </message>
        <message>
            <source>Answer to %1: %2</source>
            <translation>Answer to %1: %2</translation>
        </message>
        <message>
            <source>expected %1 data characters (%2), got %3.</source>
            <translation>expected %1 data characters (%2), got %3.</translation>
        </message>
        <message>
            <source>status byte &quot;%1&quot; is not hex.</source>
            <translation>status byte &quot;%1&quot; is not hex.</translation>
        </message>
        <message>
            <source>discrete status &quot;%1&quot; is not 0 or 1.</source>
            <translation>discrete status &quot;%1&quot; is not 0 or 1.</translation>
        </message>
        <message>
            <source>value &quot;%1&quot; is not hex.</source>
            <translation>value &quot;%1&quot; is not hex.</translation>
        </message>
        <message>
            <source>status bytes have an odd number of hex characters (%1).</source>
            <translation>status bytes have an odd number of hex characters (%1).</translation>
        </message>
        <message>
            <source>the echoed %1 bytes differ from the %2 bytes sent.</source>
            <translation>the echoed %1 bytes differ from the %2 bytes sent.</translation>
        </message>
        <message>
            <source>the error byte is missing.</source>
            <translation>the error byte is missing.</translation>
        </message>
        <message>
            <source>%1 data bytes instead of %2 (%3).</source>
            <translation>%1 data bytes instead of %2 (%3).</translation>
        </message>
        <message>
            <source>value %1 for %2 is neither 00 nor 01.</source>
            <translation>value %1 for %2 is neither 00 nor 01.</translation>
        </message>
        <message>
            <source>Answer from station %1 while station %2 was asked (%3).</source>
            <translation>Answer from station %1 while station %2 was asked (%3).</translation>
        </message>
        <message>
            <source>Answer to command %1 while %2 (%3) was sent.</source>
            <translation>Answer to command %1 while %2 (%3) was sent.</translation>
        </message>
        <message>
            <source>Answer to command %1 while %2 was sent (%3).</source>
            <translation>Answer to command %1 while %2 was sent (%3).</translation>
        </message>
        <message>
            <source>Loopback data differs: sent &quot;%1&quot;, received &quot;%2&quot;.</source>
            <translation>Loopback data differs: sent &quot;%1&quot;, received &quot;%2&quot;.</translation>
        </message>
        <message>
            <source>Answer to %1 has no error digit.</source>
            <translation>Answer to %1 has no error digit.</translation>
        </message>
        <message>
            <source>Answer to %1: error digit &quot;%2&quot; is not hex.</source>
            <translation>Answer to %1: error digit &quot;%2&quot; is not hex.</translation>
        </message>
        <message>
            <source>%1: %2 data characters; a FACON frame carries at most 500.</source>
            <translation>%1: %2 data characters; a FACON frame carries at most 500.</translation>
        </message>
        <message>
            <source>Received a query frame (51) instead of an answer (52): probably the echo of our own query.</source>
            <translation>Received a query frame (51) instead of an answer (52): probably the echo of our own query.</translation>
        </message>
        <message>
            <source>FACON frame too short (%1 bytes; at least 8: STX, station, command, LRC, ETX).</source>
            <translation>FACON frame too short (%1 bytes; at least 8: STX, station, command, LRC, ETX).</translation>
        </message>
        <message>
            <source>FACON frame too long (%1 bytes; at most %2).</source>
            <translation>FACON frame too long (%1 bytes; at most %2).</translation>
        </message>
        <message>
            <source>FACON frame does not start with STX.</source>
            <translation>FACON frame does not start with STX.</translation>
        </message>
        <message>
            <source>FACON frame does not end with ETX.</source>
            <translation>FACON frame does not end with ETX.</translation>
        </message>
        <message>
            <source>FACON frame contains a stray STX or ETX inside.</source>
            <translation>FACON frame contains a stray STX or ETX inside.</translation>
        </message>
        <message>
            <source>FACON frame header &quot;%1&quot; is not station and command in hex.</source>
            <translation>FACON frame header &quot;%1&quot; is not station and command in hex.</translation>
        </message>
        <message>
            <source>FACON checksum &quot;%1&quot; is not two hex characters.</source>
            <translation>FACON checksum &quot;%1&quot; is not two hex characters.</translation>
        </message>
        <message>
            <source>FACON checksum error: frame says %1, computed %2.</source>
            <translation>FACON checksum error: frame says %1, computed %2.</translation>
        </message>
        <message>
            <source>FACON frame too short (%1 bytes): station, command and LRC do not fit.</source>
            <translation>FACON frame too short (%1 bytes): station, command and LRC do not fit.</translation>
        </message>
        <message>
            <source>FACON frame with a non-hex station or command.</source>
            <translation>FACON frame with a non-hex station or command.</translation>
        </message>
        <message>
            <source>FACON frame whose checksum is not two hex characters.</source>
            <translation>FACON frame whose checksum is not two hex characters.</translation>
        </message>
        <message>
            <source>Incomplete FACON frame: a new STX arrived before ETX.</source>
            <translation>Incomplete FACON frame: a new STX arrived before ETX.</translation>
        </message>
        <message>
            <source>FACON frame without ETX within %1 bytes.</source>
            <translation>FACON frame without ETX within %1 bytes.</translation>
        </message>
        <message>
            <source>Binary frame too short (%1 bytes): a frame has at least 10 bytes.</source>
            <translation>Binary frame too short (%1 bytes): a frame has at least 10 bytes.</translation>
        </message>
        <message>
            <source>Binary frame starts with %1 instead of 51 (query) or 52 (answer).</source>
            <translation>Binary frame starts with %1 instead of 51 (query) or 52 (answer).</translation>
        </message>
        <message>
            <source>Binary frame ID is %1 instead of 10.</source>
            <translation>Binary frame ID is %1 instead of 10.</translation>
        </message>
        <message>
            <source>Binary frame length field says %1 payload bytes but the frame carries %2.</source>
            <translation>Binary frame length field says %1 payload bytes but the frame carries %2.</translation>
        </message>
        <message>
            <source>Binary frame ends with %1 instead of the terminator 55 AA.</source>
            <translation>Binary frame ends with %1 instead of the terminator 55 AA.</translation>
        </message>
        <message>
            <source>Binary frame CRC is %1, computed %2.</source>
            <translation>Binary frame CRC is %1, computed %2.</translation>
        </message>
        <message>
            <source>Binary frame without station and command.</source>
            <translation>Binary frame without station and command.</translation>
        </message>
        <message>
            <source>Binary frame of %1 bytes does not end with the terminator 55 AA.</source>
            <translation>Binary frame of %1 bytes does not end with the terminator 55 AA.</translation>
        </message>
        <message>
            <source>Binary frame of %1 bytes has a wrong CRC (line noise or a broken frame).</source>
            <translation>Binary frame of %1 bytes has a wrong CRC (line noise or a broken frame).</translation>
        </message>
        <message>
            <source>%1 series, %2-word program</source>
            <translation>%1 series, %2-word program</translation>
        </message>
        <message>
            <source>Cannot read the program backup %1: %2</source>
            <translation>Cannot read the program backup %1: %2</translation>
        </message>
        <message>
            <source>Cannot write the program backup %1: %2</source>
            <translation>Cannot write the program backup %1: %2</translation>
        </message>
        <message>
            <source>The program backup is not valid JSON: %1</source>
            <translation>The program backup is not valid JSON: %1</translation>
        </message>
        <message>
            <source>The file is not a program backup (format &quot;%1&quot;, expected &quot;fatek-program&quot;).</source>
            <translation>The file is not a program backup (format &quot;%1&quot;, expected &quot;fatek-program&quot;).</translation>
        </message>
        <message>
            <source>The program backup has format version %1, which this program cannot read.</source>
            <translation>The program backup has format version %1, which this program cannot read.</translation>
        </message>
        <message>
            <source>The program backup is damaged: the field &quot;%1&quot; is missing or wrong.</source>
            <translation>The program backup is damaged: the field &quot;%1&quot; is missing or wrong.</translation>
        </message>
        <message>
            <source>The program backup is damaged or truncated: it holds %1 pages, its header needs %2.</source>
            <translation>The program backup is damaged or truncated: it holds %1 pages, its header needs %2.</translation>
        </message>
        <message>
            <source>The program backup is damaged: page %1 is not 64 words of 4 hex digits.</source>
            <translation>The program backup is damaged: page %1 is not 64 words of 4 hex digits.</translation>
        </message>
        <message>
            <source>The program backup is damaged: its checksum is %1, its words give %2.</source>
            <translation>The program backup is damaged: its checksum is %1, its words give %2.</translation>
        </message>
        <message>
            <source>The program backup is damaged: page 0 is not a program header.</source>
            <translation>The program backup is damaged: page 0 is not a program header.</translation>
        </message>
        <message>
            <source>No connection to a PLC.</source>
            <translation>No connection to a PLC.</translation>
        </message>
        <message>
            <source>A program transfer is already running.</source>
            <translation>A program transfer is already running.</translation>
        </message>
        <message>
            <source>Operator mode: restoring a program is refused; nothing was written.</source>
            <translation>Operator mode: restoring a program is refused; nothing was written.</translation>
        </message>
        <message>
            <source>The PLC is in RUN: switch it to STOP before restoring a program; nothing was written.</source>
            <translation>The PLC is in RUN: switch it to STOP before restoring a program; nothing was written.</translation>
        </message>
        <message>
            <source>The PLC did not report its program size (detail status 53).</source>
            <translation>The PLC did not report its program size (detail status 53).</translation>
        </message>
        <message>
            <source>The PLC's page 0 is not a program header.</source>
            <translation>The PLC's page 0 is not a program header.</translation>
        </message>
        <message>
            <source>The backup is for a %1, the PLC holds a %2: not restored, nothing was written.</source>
            <translation>The backup is for a %1, the PLC holds a %2: not restored, nothing was written.</translation>
        </message>
        <message>
            <source>%1 with a %2-word program</source>
            <translation>%1 with a %2-word program</translation>
        </message>
        <message>
            <source>%1-word program (the PLC does not name its model)</source>
            <translation>%1-word program (the PLC does not name its model)</translation>
        </message>
        <message>
            <source>Reading program page %1 failed: %2</source>
            <translation>Reading program page %1 failed: %2</translation>
        </message>
        <message>
            <source>Writing program page %1 failed: %2</source>
            <translation>Writing program page %1 failed: %2</translation>
        </message>
        <message>
            <source>%1 The PLC now holds a mixed program (%2 of %3 {3:page|pages} written from the backup, the rest from its old program) and stays in STOP: restore the same file again before switching it to RUN.</source>
            <translation>%1 The PLC now holds a mixed program (%2 of %3 {3:page|pages} written from the backup, the rest from its old program) and stays in STOP: restore the same file again before switching it to RUN.</translation>
        </message>
        <message>
            <source>Verification failed: %1 {1:page|pages} on the PLC {1:differs|differ} from the backup (%2).</source>
            <translation>Verification failed: %1 {1:page|pages} on the PLC {1:differs|differ} from the backup (%2).</translation>
        </message>
        <message>
            <source>Backup cancelled at page %1 (%2 of %3 {3:page|pages} read); no file saved.</source>
            <translation>Backup cancelled at page %1 (%2 of %3 {3:page|pages} read); no file saved.</translation>
        </message>
        <message>
            <source>Restore cancelled at page %1 (%2 of %3 {3:page|pages} written): the PLC's program is incomplete.</source>
            <translation>Restore cancelled at page %1 (%2 of %3 {3:page|pages} written): the PLC's program is incomplete.</translation>
        </message>
        <message>
            <source>Cancelled before anything was written.</source>
            <translation>Cancelled before anything was written.</translation>
        </message>
        <message>
            <source>Backup done: %1 {1:page|pages} of a %2.</source>
            <translation>Backup done: %1 {1:page|pages} of a %2.</translation>
        </message>
        <message>
            <source>Restore done: %1 {1:page|pages} written and verified.</source>
            <translation>Restore done: %1 {1:page|pages} written and verified.</translation>
        </message>
        <message>
            <source>%1 {1:page differs|pages differ} from the PLC (%2).</source>
            <translation>%1 {1:page differs|pages differ} from the PLC (%2).</translation>
        </message>
        <message>
            <source>The PLC already holds this program.</source>
            <translation>The PLC already holds this program.</translation>
        </message>
        <message>
            <source>Reading the program</source>
            <translation>Reading the program</translation>
        </message>
        <message>
            <source>Writing the program</source>
            <translation>Writing the program</translation>
        </message>
        <message>
            <source>Reading the program back to verify</source>
            <translation>Reading the program back to verify</translation>
        </message>
        <message>
            <source>Verification cancelled at page %1 (%2 of %3 {3:page|pages} checked); the program was written completely.</source>
            <translation>Verification cancelled at page %1 (%2 of %3 {3:page|pages} checked); the program was written completely.</translation>
        </message>
        <message>
            <source>No connection to read from.</source>
            <translation>No connection to read from.</translation>
        </message>
        <message>
            <source>A snapshot or restore is already running.</source>
            <translation>A snapshot or restore is already running.</translation>
        </message>
        <message>
            <source>The PLC did not report its memory sizes (%1): give the ranges to read.</source>
            <translation>The PLC did not report its memory sizes (%1): give the ranges to read.</translation>
        </message>
        <message>
            <source>No element ranges to read.</source>
            <translation>No element ranges to read.</translation>
        </message>
        <message>
            <source>%1 elements are more than a snapshot holds (at most %2).</source>
            <translation>%1 elements are more than a snapshot holds (at most %2).</translation>
        </message>
        <message>
            <source>Cannot read %1: %2</source>
            <translation>Cannot read %1: %2</translation>
        </message>
        <message>
            <source>The file is not UTF-8 text, and this build cannot decode Big5.</source>
            <translation>The file is not UTF-8 text, and this build cannot decode Big5.</translation>
        </message>
        <message>
            <source>the line is neither UTF-8 nor Big5 text</source>
            <translation>the line is neither UTF-8 nor Big5 text</translation>
        </message>
        <message>
            <source>no address in the first column</source>
            <translation>no address in the first column</translation>
        </message>
        <message>
            <source>%1 has neither a name nor a comment</source>
            <translation>%1 has neither a name nor a comment</translation>
        </message>
        <message>
            <source>a quoted field is not closed on its line (missing &quot;)</source>
            <translation>a quoted field is not closed on its line (missing &quot;)</translation>
        </message>
        <message>
            <source>text after the quoted field &quot;%1&quot;</source>
            <translation>text after the quoted field &quot;%1&quot;</translation>
        </message>
        <message>
            <source>Names imported: %1, lines skipped: %2</source>
            <translation>Names imported: %1, lines skipped: %2</translation>
        </message>
        <message>
            <source>Names imported: %1, lines skipped: %2 (%3)</source>
            <translation>Names imported: %1, lines skipped: %2 (%3)</translation>
        </message>
        <message>
            <source>and %1 more</source>
            <translation>and %1 more</translation>
        </message>
        <message>
            <source>%1; read as Big5</source>
            <translation>%1; read as Big5</translation>
        </message>
        <message>
            <source>symbol %1</source>
            <translation>symbol %1</translation>
        </message>
        <message>
            <source>Cancelled.</source>
            <translation>Cancelled.</translation>
        </message>
        <message>
            <source>%1 {1:value|values} read in %2 {2:request|requests}.</source>
            <translation>%1 {1:value|values} read in %2 {2:request|requests}.</translation>
        </message>
        <message>
            <source>value %1</source>
            <translation>value %1</translation>
        </message>
        <message>
            <source>line %1, column %2</source>
            <translation>line %1, column %2</translation>
        </message>
        <message>
            <source>%1: a snapshot file name ends in .json or .csv.</source>
            <translation>%1: a snapshot file name ends in .json or .csv.</translation>
        </message>
        <message>
            <source>Cannot open %1: %2</source>
            <translation>Cannot open %1: %2</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>Cannot write %1: %2</translation>
        </message>
        <message>
            <source>not valid JSON (%1)</source>
            <translation>not valid JSON (%1)</translation>
        </message>
        <message>
            <source>not a memory snapshot (&quot;format&quot; is not &quot;%1&quot;)</source>
            <translation>not a memory snapshot (&quot;format&quot; is not &quot;%1&quot;)</translation>
        </message>
        <message>
            <source>snapshot version %1 is not supported (this program reads %2)</source>
            <translation>snapshot version %1 is not supported (this program reads %2)</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is missing</source>
            <translation>&quot;%1&quot; is missing</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a whole number</source>
            <translation>&quot;%1&quot; is not a whole number</translation>
        </message>
        <message>
            <source>%1 does not fit %2 (0..%3)</source>
            <translation>%1 does not fit %2 (0..%3)</translation>
        </message>
        <message>
            <source>the hex column %1 differs from the value %2</source>
            <translation>the hex column %1 differs from the value %2</translation>
        </message>
        <message>
            <source>%1 appears twice</source>
            <translation>%1 appears twice</translation>
        </message>
        <message>
            <source>expected address,value[,hex]</source>
            <translation>expected address,value[,hex]</translation>
        </message>
        <message>
            <source>a metadata line reads &quot;# key: value&quot;</source>
            <translation>a metadata line reads &quot;# key: value&quot;</translation>
        </message>
        <message>
            <source>the snapshot holds no values</source>
            <translation>the snapshot holds no values</translation>
        </message>
        <message>
            <source>(absent)</source>
            <translation>(absent)</translation>
        </message>
        <message>
            <source>%1: %2 -&gt; %3</source>
            <translation>%1: %2 -&gt; %3</translation>
        </message>
        <message>
            <source>No differences.</source>
            <translation>No differences.</translation>
        </message>
        <message>
            <source>%1 of %2 {2:value|values} {1:differs|differ}.</source>
            <translation>%1 of %2 {2:value|values} {1:differs|differ}.</translation>
        </message>
        <message>
            <source>Operator mode: restoring values is refused; nothing was written.</source>
            <translation>Operator mode: restoring values is refused; nothing was written.</translation>
        </message>
        <message>
            <source>The chosen ranges hold no value of the snapshot: nothing to write.</source>
            <translation>The chosen ranges hold no value of the snapshot: nothing to write.</translation>
        </message>
        <message>
            <source>Writing %1 failed: %2</source>
            <translation>Writing %1 failed: %2</translation>
        </message>
        <message>
            <source>%1 %2 of %3 {3:value|values} had been written when it stopped; the others may still hold their old values: restore the same file again.</source>
            <translation>%1 %2 of %3 {3:value|values} had been written when it stopped; the others may still hold their old values: restore the same file again.</translation>
        </message>
        <message>
            <source>Reading the values back failed: %1</source>
            <translation>Reading the values back failed: %1</translation>
        </message>
        <message>
            <source>%1 of %2 {2:value|values} {1:differs|differ} after the write (read back).</source>
            <translation>%1 of %2 {2:value|values} {1:differs|differ} after the write (read back).</translation>
        </message>
        <message>
            <source>%1 {1:value|values} written in %2 {2:request|requests} and read back equal.</source>
            <translation>%1 {1:value|values} written in %2 {2:request|requests} and read back equal.</translation>
        </message>
        <message>
            <source>The snapshot is of another model (%1) than the PLC (%2): not restored, nothing was written.</source>
            <translation>The snapshot is of another model (%1) than the PLC (%2): not restored, nothing was written.</translation>
        </message>
        <message>
            <source>%2 {2:value|values} of the snapshot {2:is|are} not on the PLC: %1. The PLC (%3) has %4. Not restored, nothing was written.</source>
            <translation>%2 {2:value|values} of the snapshot {2:is|are} not on the PLC: %1. The PLC (%3) has %4. Not restored, nothing was written.</translation>
        </message>
        <message>
            <source>Reading the PLC's model and ranges failed (%1): nothing was written.</source>
            <translation>Reading the PLC's model and ranges failed (%1): nothing was written.</translation>
        </message>
        <message>
            <source>%1 cannot be checked: a checkout takes inputs X, outputs Y and registers R or D.</source>
            <translation>%1 cannot be checked: a checkout takes inputs X, outputs Y and registers R or D.</translation>
        </message>
        <message>
            <source>The checkout plan holds no points.</source>
            <translation>The checkout plan holds no points.</translation>
        </message>
        <message>
            <source>%1 appears twice in the checkout plan.</source>
            <translation>%1 appears twice in the checkout plan.</translation>
        </message>
        <message>
            <source>No imported name of an input or output starts with &quot;%1&quot;.</source>
            <translation>No imported name of an input or output starts with &quot;%1&quot;.</translation>
        </message>
        <message>
            <source>checkout plan line %1: %2</source>
            <translation>checkout plan line %1: %2</translation>
        </message>
        <message>
            <source>expected the columns %1</source>
            <translation>expected the columns %1</translation>
        </message>
        <message>
            <source>%1: an analog point needs its expected low and high values</source>
            <translation>%1: an analog point needs its expected low and high values</translation>
        </message>
        <message>
            <source>Cannot open the checkout %1: %2</source>
            <translation>Cannot open the checkout %1: %2</translation>
        </message>
        <message>
            <source>Cannot save the checkout %1: %2</source>
            <translation>Cannot save the checkout %1: %2</translation>
        </message>
        <message>
            <source>The checkout %1 is damaged: %2</source>
            <translation>The checkout %1 is damaged: %2</translation>
        </message>
        <message>
            <source>not a checkout (&quot;format&quot; is not &quot;%1&quot;)</source>
            <translation>not a checkout (&quot;format&quot; is not &quot;%1&quot;)</translation>
        </message>
        <message>
            <source>No connection to a PLC: the checkout waits.</source>
            <translation>No connection to a PLC: the checkout waits.</translation>
        </message>
        <message>
            <source>Operator mode: testing outputs is refused; nothing was forced.</source>
            <translation>Operator mode: testing outputs is refused; nothing was forced.</translation>
        </message>
        <message>
            <source>%1 is still under test: answer for it before the next output.</source>
            <translation>%1 is still under test: answer for it before the next output.</translation>
        </message>
        <message>
            <source>%1 is not an output of the checkout plan.</source>
            <translation>%1 is not an output of the checkout plan.</translation>
        </message>
        <message>
            <source>%1 changed while testing %2: crossed wiring?</source>
            <translation>%1 changed while testing %2: crossed wiring?</translation>
        </message>
        <message>
            <source>The PLC is in RUN: its program drives the outputs too. Force %1 on anyway? Yes: %1 and then each output tested is forced on until its answer, whatever the program does. No: nothing is forced.</source>
            <translation>The PLC is in RUN: its program drives the outputs too. Force %1 on anyway? Yes: %1 and then each output tested is forced on until its answer, whatever the program does. No: nothing is forced.</translation>
        </message>
        <message>
            <source>Not forced: the PLC is in RUN and forcing was not confirmed. The outputs stay untested.</source>
            <translation>Not forced: the PLC is in RUN and forcing was not confirmed. The outputs stay untested.</translation>
        </message>
        <message>
            <source>Forcing %1 failed: %2</source>
            <translation>Forcing %1 failed: %2</translation>
        </message>
        <message>
            <source>Releasing %1 failed: %2. It stays recorded as forced; the release is tried again until the PLC confirms it.</source>
            <translation>Releasing %1 failed: %2. It stays recorded as forced; the release is tried again until the PLC confirms it.</translation>
        </message>
        <message>
            <source>%1 is not released yet (the PLC has not confirmed it): it is forced again only after that.</source>
            <translation>%1 is not released yet (the PLC has not confirmed it): it is forced again only after that.</translation>
        </message>
        <message>
            <source>Released the outputs the checkout had forced: %1.</source>
            <translation>Released the outputs the checkout had forced: %1.</translation>
        </message>
        <message>
            <source>The link is lost: a forced output is released as soon as it is back.</source>
            <translation>The link is lost: a forced output is released as soon as it is back.</translation>
        </message>
        <message>
            <source>Reading %1 failed: %2</source>
            <translation>Reading %1 failed: %2</translation>
        </message>
        <message>
            <source>Input</source>
            <translation>Input</translation>
        </message>
        <message>
            <source>Output</source>
            <translation>Output</translation>
        </message>
        <message>
            <source>Analog</source>
            <translation>Analog</translation>
        </message>
        <message>
            <source>Untested</source>
            <translation>Untested</translation>
        </message>
        <message>
            <source>Passed</source>
            <translation>Passed</translation>
        </message>
        <message>
            <source>Failed</source>
            <translation>Failed</translation>
        </message>
        <message>
            <source>0-&gt;1 at %1, 1-&gt;0 at %2</source>
            <translation>0-&gt;1 at %1, 1-&gt;0 at %2</translation>
        </message>
        <message>
            <source>seen in the field</source>
            <translation>seen in the field</translation>
        </message>
        <message>
            <source>not seen in the field</source>
            <translation>not seen in the field</translation>
        </message>
        <message>
            <source>also changed while it was tested: %1</source>
            <translation>also changed while it was tested: %1</translation>
        </message>
        <message>
            <source>I/O checkout report</source>
            <translation>I/O checkout report</translation>
        </message>
        <message>
            <source>Project</source>
            <translation>Project</translation>
        </message>
        <message>
            <source>Customer</source>
            <translation>Customer</translation>
        </message>
        <message>
            <source>PLC model</source>
            <translation>PLC model</translation>
        </message>
        <message>
            <source>OS version</source>
            <translation>OS version</translation>
        </message>
        <message>
            <source>PLC station</source>
            <translation>PLC station</translation>
        </message>
        <message>
            <source>Date</source>
            <translation>Date</translation>
        </message>
        <message>
            <source>Engineer</source>
            <translation>Engineer</translation>
        </message>
        <message>
            <source>not reported by the PLC</source>
            <translation>not reported by the PLC</translation>
        </message>
        <message>
            <source>Point</source>
            <translation>Point</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>Name</translation>
        </message>
        <message>
            <source>Group</source>
            <translation>Group</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>Kind</translation>
        </message>
        <message>
            <source>Result</source>
            <translation>Result</translation>
        </message>
        <message>
            <source>Measured</source>
            <translation>Measured</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>Comment</translation>
        </message>
        <message>
            <source>Tested at</source>
            <translation>Tested at</translation>
        </message>
        <message>
            <source>Summary</source>
            <translation>Summary</translation>
        </message>
        <message>
            <source>Signatures</source>
            <translation>Signatures</translation>
        </message>
        <message>
            <source>Commissioning engineer</source>
            <translation>Commissioning engineer</translation>
        </message>
        <message>
            <source>Customer representative</source>
            <translation>Customer representative</translation>
        </message>
        <message>
            <source>Witness</source>
            <translation>Witness</translation>
        </message>
        <message>
            <source>Role</source>
            <translation>Role</translation>
        </message>
        <message>
            <source>Printed name</source>
            <translation>Printed name</translation>
        </message>
        <message>
            <source>Company</source>
            <translation>Company</translation>
        </message>
        <message>
            <source>Signature</source>
            <translation>Signature</translation>
        </message>
        <message>
            <source>Tested</source>
            <translation>Tested</translation>
        </message>
        <message>
            <source>%1 to %2</source>
            <translation>%1 to %2</translation>
        </message>
        <message>
            <source>nothing recorded yet</source>
            <translation>nothing recorded yet</translation>
        </message>
        <message>
            <source>Report made</source>
            <translation>Report made</translation>
        </message>
        <message>
            <source>%1 (%2 {2:point|points})</source>
            <translation>%1 (%2 {2:point|points})</translation>
        </message>
        <message>
            <source>not named</source>
            <translation>not named</translation>
        </message>
        <message>
            <source>Page %1 of %2</source>
            <translation>Page %1 of %2</translation>
        </message>
        <message>
            <source>Results</source>
            <translation>Results</translation>
        </message>
        
        <message>
            <source>Not tested (%1): %2</source>
            <translation>Not tested (%1): %2</translation>
        </message>
        <message>
            <source>Cannot write the report %1: %2</source>
            <translation>Cannot write the report %1: %2</translation>
        </message>
        <message>
            <source>%1: a report file name ends in .pdf or .csv.</source>
            <translation>%1: a report file name ends in .pdf or .csv.</translation>
        </message>
        <message>
            <source>No broker given.</source>
            <translation>No broker given.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a broker address: write mqtt://host:1883 or mqtts://user@host:8883.</source>
            <translation>&quot;%1&quot; is not a broker address: write mqtt://host:1883 or mqtts://user@host:8883.</translation>
        </message>
        <message>
            <source>refused a command on &quot;%1&quot;: %2</source>
            <translation>refused a command on &quot;%1&quot;: %2</translation>
        </message>
        <message>
            <source>station %1 does not answer: %2</source>
            <translation>station %1 does not answer: %2</translation>
        </message>
        <message>
            <source>station %1 demoted: %2</source>
            <translation>station %1 demoted: %2</translation>
        </message>
        <message>
            <source>station %1 answers again</source>
            <translation>station %1 answers again</translation>
        </message>
        <message>
            <source>station %1 %2: %3</source>
            <translation>station %1 %2: %3</translation>
        </message>
        <message>
            <source>station %1 %2 read again</source>
            <translation>station %1 %2 read again</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a host: write an IP address (192.168.1.5) or a host name (letters, digits, &apos;-&apos; and &apos;.&apos;).</source>
            <translation>&quot;%1&quot; is not a host: write an IP address (192.168.1.5) or a host name (letters, digits, &apos;-&apos; and &apos;.&apos;).</translation>
        </message>
        <message>
            <source>Connections &quot;%1&quot; and &quot;%2&quot; would get the same Home Assistant id &quot;%3&quot; (characters other than letters, digits, &apos;-&apos; and &apos;_&apos; become &apos;_&apos;): rename one.</source>
            <translation>Connections &quot;%1&quot; and &quot;%2&quot; would get the same Home Assistant id &quot;%3&quot; (characters other than letters, digits, &apos;-&apos; and &apos;_&apos; become &apos;_&apos;): rename one.</translation>
        </message>
        <message>
            <source>%1 is a TLS setting, but the broker URL is mqtt:// (clear text): write mqtts://, or remove %1.</source>
            <translation>%1 is a TLS setting, but the broker URL is mqtt:// (clear text): write mqtts://, or remove %1.</translation>
        </message>
        <message>
            <source>The CA file %1 holds no usable certificate: %2.</source>
            <translation>The CA file %1 holds no usable certificate: %2.</translation>
        </message>
        <message>
            <source>The certificate file %1 is not usable: %2.</source>
            <translation>The certificate file %1 is not usable: %2.</translation>
        </message>
        <message>
            <source>The key file %1 is not usable: %2.</source>
            <translation>The key file %1 is not usable: %2.</translation>
        </message>
        <message>
            <source>The key file %1 is not the key of the certificate %2.</source>
            <translation>The key file %1 is not the key of the certificate %2.</translation>
        </message>
        <message>
            <source>The broker %1 closed the connection right after accepting it, %2 times in a row: another client with the same client id &quot;%3&quot; took over (a second gateway with this configuration?); trying again less often.</source>
            <translation>The broker %1 closed the connection right after accepting it, %2 times in a row: another client with the same client id &quot;%3&quot; took over (a second gateway with this configuration?); trying again less often.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; must be a string.</source>
            <translation>&quot;%1&quot; must be a string.</translation>
        </message>
        <message>
            <source>Cannot read the TLS file %1.</source>
            <translation>Cannot read the TLS file %1.</translation>
        </message>
        <message>
            <source>A client certificate needs its key file, and a key its certificate.</source>
            <translation>A client certificate needs its key file, and a key its certificate.</translation>
        </message>
        <message>
            <source>%1 needs TLS, which this build&apos;s MQTT library does not have (the Windows build has none yet): use an mqtt:// broker.</source>
            <translation>%1 needs TLS, which this build&apos;s MQTT library does not have (the Windows build has none yet): use an mqtt:// broker.</translation>
        </message>
        <message>
            <source>A broker password needs a user name.</source>
            <translation>A broker password needs a user name.</translation>
        </message>
        <message>
            <source>Broker timing out of range: keep-alive at least 5 s, reconnect delays at least 10 ms, the longest not below the first.</source>
            <translation>Broker timing out of range: keep-alive at least 5 s, reconnect delays at least 10 ms, the longest not below the first.</translation>
        </message>
        <message>
            <source>Cannot reach the broker %1: %2</source>
            <translation>Cannot reach the broker %1: %2</translation>
        </message>
        <message>
            <source>the broker closed the connection before accepting it</source>
            <translation>the broker closed the connection before accepting it</translation>
        </message>
        <message>
            <source>%1; the broker may require a client certificate, and none is configured (certFile, keyFile)</source>
            <translation>%1; the broker may require a client certificate, and none is configured (certFile, keyFile)</translation>
        </message>
        <message>
            <source>the TLS handshake failed</source>
            <translation>the TLS handshake failed</translation>
        </message>
        <message>
            <source>%1 (the library says: %2)</source>
            <translation>%1 (the library says: %2)</translation>
        </message>
        <message>
            <source>The broker %1 refused us: %2</source>
            <translation>The broker %1 refused us: %2</translation>
        </message>
        <message>
            <source>Link to the broker %1 lost: %2</source>
            <translation>Link to the broker %1 lost: %2</translation>
        </message>
        <message>
            <source>Disconnected from the broker %1.</source>
            <translation>Disconnected from the broker %1.</translation>
        </message>
        <message>
            <source>keep-alive timeout: the broker did not answer within %1 s</source>
            <translation>keep-alive timeout: the broker did not answer within %1 s</translation>
        </message>
        <message>
            <source>MQTT library error: %1</source>
            <translation>MQTT library error: %1</translation>
        </message>
        <message>
            <source>The command starts with { but is not a JSON object.</source>
            <translation>The command starts with { but is not a JSON object.</translation>
        </message>
        <message>
            <source>The command has no value: send the text to write, or {&quot;value&quot;: ...}.</source>
            <translation>The command has no value: send the text to write, or {&quot;value&quot;: ...}.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a value format.</source>
            <translation>&quot;%1&quot; is not a value format.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; must be %2 or %3.</source>
            <translation>&quot;%1&quot; must be %2 or %3.</translation>
        </message>
        <message>
            <source>&quot;words&quot; must be a list of whole numbers from 0 to 4294967295.</source>
            <translation>&quot;words&quot; must be a list of whole numbers from 0 to 4294967295.</translation>
        </message>
        <message>
            <source>The command has %1 word(s), but %2 in this format spans %3.</source>
            <translation>The command has %1 word(s), but %2 in this format spans %3.</translation>
        </message>
        <message>
            <source>&quot;id&quot; must be text or a number.</source>
            <translation>&quot;id&quot; must be text or a number.</translation>
        </message>
        <message>
            <source>Refused: the command&apos;s &quot;time&quot; is %1 s ahead of the gateway&apos;s clock (at most %2 s are taken); check the sender&apos;s clock.</source>
            <translation>Refused: the command&apos;s &quot;time&quot; is %1 s ahead of the gateway&apos;s clock (at most %2 s are taken); check the sender&apos;s clock.</translation>
        </message>
        <message>
            <source>%1 (station %2) is not published by the gateway %3.</source>
            <translation>%1 (station %2) is not published by the gateway %3.</translation>
        </message>
        <message>
            <source>No status from the gateway %1 yet.</source>
            <translation>No status from the gateway %1 yet.</translation>
        </message>
        <message>
            <source>The gateway %1 is connecting to its PLC.</source>
            <translation>The gateway %1 is connecting to its PLC.</translation>
        </message>
        <message>
            <source>The gateway %1 is offline.</source>
            <translation>The gateway %1 is offline.</translation>
        </message>
        <message>
            <source>The gateway %1 is offline: %2</source>
            <translation>The gateway %1 is offline: %2</translation>
        </message>
        <message>
            <source>The gateway %1 lost its link to the PLC.</source>
            <translation>The gateway %1 lost its link to the PLC.</translation>
        </message>
        <message>
            <source>The gateway %1 lost its link to the PLC: %2</source>
            <translation>The gateway %1 lost its link to the PLC: %2</translation>
        </message>
        <message>
            <source>%1 was not sent: %2</source>
            <translation>%1 was not sent: %2</translation>
        </message>
        <message>
            <source>The broker %1 did not take the command.</source>
            <translation>The broker %1 did not take the command.</translation>
        </message>
        <message>
            <source>No reply from the gateway %1 within %2 s.</source>
            <translation>No reply from the gateway %1 within %2 s.</translation>
        </message>
        <message>
            <source>The gateway %1 did not write the value.</source>
            <translation>The gateway %1 did not write the value.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a topic prefix: levels separated by /, without + or #.</source>
            <translation>&quot;%1&quot; is not a topic prefix: levels separated by /, without + or #.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a gateway connection name: 1 to 64 letters, digits, -, _ or ., and not a number.</source>
            <translation>&quot;%1&quot; is not a gateway connection name: 1 to 64 letters, digits, -, _ or ., and not a number.</translation>
        </message>
        <message>
            <source>The configuration is not a JSON object: %1</source>
            <translation>The configuration is not a JSON object: %1</translation>
        </message>
        <message>
            <source>Not a gateway configuration: &quot;%1&quot; must be &quot;%2&quot;.</source>
            <translation>Not a gateway configuration: &quot;%1&quot; must be &quot;%2&quot;.</translation>
        </message>
        <message>
            <source>Configuration version %1 is not supported (this program reads version %2).</source>
            <translation>Configuration version %1 is not supported (this program reads version %2).</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is missing.</source>
            <translation>&quot;%1&quot; is missing.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; must be %2.</source>
            <translation>&quot;%1&quot; must be %2.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a known setting.</source>
            <translation>&quot;%1&quot; is not a known setting.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a known setting; did you mean &quot;%2&quot;?</source>
            <translation>&quot;%1&quot; is not a known setting; did you mean &quot;%2&quot;?</translation>
        </message>
        <message>
            <source>a string</source>
            <translation>a string</translation>
        </message>
        <message>
            <source>a whole number</source>
            <translation>a whole number</translation>
        </message>
        <message>
            <source>%1 or %2</source>
            <translation>%1 or %2</translation>
        </message>
        <message>
            <source>a list</source>
            <translation>a list</translation>
        </message>
        <message>
            <source>an object</source>
            <translation>an object</translation>
        </message>
        <message>
            <source>%1 %2 is out of range (%3..%4)</source>
            <translation>%1 %2 is out of range (%3..%4)</translation>
        </message>
        <message>
            <source>No connections: the configuration needs at least one.</source>
            <translation>No connections: the configuration needs at least one.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a usable connection name: 1 to 64 letters, digits, &apos;-&apos;, &apos;_&apos; or &apos;.&apos;, and not a number.</source>
            <translation>&quot;%1&quot; is not a usable connection name: 1 to 64 letters, digits, &apos;-&apos;, &apos;_&apos; or &apos;.&apos;, and not a number.</translation>
        </message>
        <message>
            <source>The connection name &quot;%1&quot; is used twice.</source>
            <translation>The connection name &quot;%1&quot; is used twice.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a usable topic prefix: levels separated by &apos;/&apos;, none empty, without &apos;+&apos;, &apos;#&apos; or a NUL character, not starting with &apos;$&apos;.</source>
            <translation>&quot;%1&quot; is not a usable topic prefix: levels separated by &apos;/&apos;, none empty, without &apos;+&apos;, &apos;#&apos; or a NUL character, not starting with &apos;$&apos;.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a link kind: write %2, %3 or %4.</source>
            <translation>&quot;%1&quot; is not a link kind: write %2, %3 or %4.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a protocol: write %2, %3 or %4.</source>
            <translation>&quot;%1&quot; is not a protocol: write %2, %3 or %4.</translation>
        </message>
        <message>
            <source>Nothing to watch: give at least one watch list with items.</source>
            <translation>Nothing to watch: give at least one watch list with items.</translation>
        </message>
        <message>
            <source>station %1 %2 is watched twice (each address has one topic)</source>
            <translation>station %1 %2 is watched twice (each address has one topic)</translation>
        </message>
        <message>
            <source>Give the broker &quot;%1&quot; or a &quot;%2&quot;, not both.</source>
            <translation>Give the broker &quot;%1&quot; or a &quot;%2&quot;, not both.</translation>
        </message>
        <message>
            <source>connection %1 (%2)</source>
            <translation>connection %1 (%2)</translation>
        </message>
        <message>
            <source>connection %1</source>
            <translation>connection %1</translation>
        </message>
        <message>
            <source>link</source>
            <translation>link</translation>
        </message>
        <message>
            <source>broker</source>
            <translation>broker</translation>
        </message>
        <message>
            <source>watch list %1</source>
            <translation>watch list %1</translation>
        </message>
        <message>
            <source>allow &quot;%1&quot;</source>
            <translation>allow &quot;%1&quot;</translation>
        </message>
        <message>
            <source>not read in this cycle</source>
            <translation>not read in this cycle</translation>
        </message>
        <message>
            <source>duplicate key &quot;%1&quot;</source>
            <translation>duplicate key &quot;%1&quot;</translation>
        </message>
        <message>
            <source>There is no alarm %1.</source>
            <translation>There is no alarm %1.</translation>
        </message>
        <message>
            <source>Alarm %1 has nothing to acknowledge (it is not unacknowledged).</source>
            <translation>Alarm %1 has nothing to acknowledge (it is not unacknowledged).</translation>
        </message>
        <message>
            <source>Alarm %1 is not shelved.</source>
            <translation>Alarm %1 is not shelved.</translation>
        </message>
        <message>
            <source>Alarm %1 cannot be shelved until a time that has passed.</source>
            <translation>Alarm %1 cannot be shelved until a time that has passed.</translation>
        </message>
        <message>
            <source>Alarm %1 is out of service (disabled in its definition).</source>
            <translation>Alarm %1 is out of service (disabled in its definition).</translation>
        </message>
        <message>
            <source>Refused: no alarm &quot;%1&quot; on this connection.</source>
            <translation>Refused: no alarm &quot;%1&quot; on this connection.</translation>
        </message>
        <message>
            <source>Refused: a retained alarm command would be carried out again at every restart; publish it without the retain flag.</source>
            <translation>Refused: a retained alarm command would be carried out again at every restart; publish it without the retain flag.</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a key of this alarm command (it takes %2).</source>
            <translation>&quot;%1&quot; is not a key of this alarm command (it takes %2).</translation>
        </message>
        <message>
            <source>&quot;%1&quot; must be text.</source>
            <translation>&quot;%1&quot; must be text.</translation>
        </message>
        <message>
            <source>A shelve needs &quot;until&quot; (ISO 8601 with its offset, ahead of now) or &quot;durationSec&quot; (1..%1), one of the two.</source>
            <translation>A shelve needs &quot;until&quot; (ISO 8601 with its offset, ahead of now) or &quot;durationSec&quot; (1..%1), one of the two.</translation>
        </message>
        <message>
            <source>alarm %1 raised (%2 priority): %3 (value %4)</source>
            <translation>alarm %1 raised (%2 priority): %3 (value %4)</translation>
        </message>
        <message>
            <source>alarm %1 returned to normal: %2 (value %3)</source>
            <translation>alarm %1 returned to normal: %2 (value %3)</translation>
        </message>
        <message>
            <source>alarm %1 %2 by %3 (comment &quot;%4&quot;)</source>
            <translation>alarm %1 %2 by %3 (comment &quot;%4&quot;)</translation>
        </message>
        <message>
            <source>alarm %1 %2</source>
            <translation>alarm %1 %2</translation>
        </message>
        <message>
            <source>alarm %1 %2 (id &quot;%3&quot;) refused: %4</source>
            <translation>alarm %1 %2 (id &quot;%3&quot;) refused: %4</translation>
        </message>
        <message>
            <source>alarm journal failed (alarms still run, not journaled): %1</source>
            <translation>alarm journal failed (alarms still run, not journaled): %1</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is the setting of every item recorded with &quot;recordAll&quot;: give &quot;recordAll&quot;: true, or put &quot;history&quot; on the items in their watch lists.</source>
            <translation>&quot;%1&quot; is the setting of every item recorded with &quot;recordAll&quot;: give &quot;recordAll&quot;: true, or put &quot;history&quot; on the items in their watch lists.</translation>
        </message>
        <message>
            <source>The history store&apos;s URL holds a password: keep it in ~/.pgpass or $PGPASSWORD (the service&apos;s EnvironmentFile), out of the configuration.</source>
            <translation>The history store's URL holds a password: keep it in ~/.pgpass or $PGPASSWORD (the service&apos;s EnvironmentFile), out of the configuration.</translation>
        </message>
        <message>
            <source>history store failed (values still polled and published, not recorded): %1</source>
            <translation>history store failed (values still polled and published, not recorded): %1</translation>
        </message>
        <message>
            <source>history store %1 written again</source>
            <translation>history store %1 written again</translation>
        </message>
        <message>
            <source>&quot;%1&quot; must name a file.</source>
            <translation>&quot;%1&quot; must name a file.</translation>
        </message>
        <message>
            <source>Cannot open the alarm journal %1: %2</source>
            <translation>Cannot open the alarm journal %1: %2</translation>
        </message>
        <message>
            <source>The alarm journal %1 does not exist.</source>
            <translation>The alarm journal %1 does not exist.</translation>
        </message>
        <message>
            <source>%1 is not an alarm journal (another program&apos;s SQLite database); it was left as it is.</source>
            <translation>%1 is not an alarm journal (another program&apos;s SQLite database); it was left as it is.</translation>
        </message>
        <message>
            <source>The alarm journal %1 has format %2, newer than this program reads (%3); it was left as it is.</source>
            <translation>The alarm journal %1 has format %2, newer than this program reads (%3); it was left as it is.</translation>
        </message>
        <message>
            <source>The alarm journal %1 is locked by another program (it holds a write transaction open).</source>
            <translation>The alarm journal %1 is locked by another program (it holds a write transaction open).</translation>
        </message>
        <message>
            <source>Cannot write to the alarm journal %1: %2</source>
            <translation>Cannot write to the alarm journal %1: %2</translation>
        </message>
        <message>
            <source>Cannot read the alarm journal %1: %2</source>
            <translation>Cannot read the alarm journal %1: %2</translation>
        </message>
        <message>
            <source>The alarm journal %1, event %2: unknown %3 &quot;%4&quot;.</source>
            <translation>The alarm journal %1, event %2: unknown %3 &quot;%4&quot;.</translation>
        </message>
        <message>
            <source>The alarm journal %1, the kept state of %2: unknown %3 &quot;%4&quot;.</source>
            <translation>The alarm journal %1, the kept state of %2: unknown %3 &quot;%4&quot;.</translation>
        </message>
        <message>
            <source>Cannot open the history store %1: %2</source>
            <translation>Cannot open the history store %1: %2</translation>
        </message>
        <message>
            <source>The history store %1 does not exist.</source>
            <translation>The history store %1 does not exist.</translation>
        </message>
        <message>
            <source>%1 is not a history store (another program&apos;s database); it was left as it is.</source>
            <translation>%1 is not a history store (another program&apos;s database); it was left as it is.</translation>
        </message>
        <message>
            <source>The history store %1 has format %2, newer than this program reads (%3); it was left as it is.</source>
            <translation>The history store %1 has format %2, newer than this program reads (%3); it was left as it is.</translation>
        </message>
        <message>
            <source>The history store %1 is locked by another program (it holds a write transaction open).</source>
            <translation>The history store %1 is locked by another program (it holds a write transaction open).</translation>
        </message>
        <message>
            <source>Cannot write to the history store %1: %2</source>
            <translation>Cannot write to the history store %1: %2</translation>
        </message>
        <message>
            <source>Cannot read the history store %1: %2</source>
            <translation>Cannot read the history store %1: %2</translation>
        </message>
        <message>
            <source>The history store %1 has no series %2.</source>
            <translation>The history store %1 has no series %2.</translation>
        </message>
        <message>
            <source>Cannot open the history store %1: this build of FATEK Studio has no PostgreSQL client (use an SQLite file).</source>
            <translation>Cannot open the history store %1: this build of FATEK Studio has no PostgreSQL client (use an SQLite file).</translation>
        </message>
        <message>
            <source>The history store %1 could not be written for a while: %2 samples were lost (the oldest).</source>
            <translation>The history store %1 could not be written for a while: %2 samples were lost (the oldest).</translation>
        </message>
        <message>
            <source>Cannot create the history store %1: cannot create its folder %2.</source>
            <translation>Cannot create the history store %1: cannot create its folder %2.</translation>
        </message>
        <message>
            <source>The history store %1 was opened to read only; nothing was written.</source>
            <translation>The history store %1 was opened to read only; nothing was written.</translation>
        </message>
        <message>
            <source>The history store %1, series %2 at %3: unknown quality %4.</source>
            <translation>The history store %1, series %2 at %3: unknown quality %4.</translation>
        </message>
        <message>
            <source>%1 is not a finite number: NaN and infinities are written only to an item whose &quot;%2&quot; option is on</source>
            <translation>%1 is not a finite number: NaN and infinities are written only to an item whose &quot;%2&quot; option is on</translation>
        </message>
        <message>
            <source>Refused: the gateway is read-only.</source>
            <translation>Refused: the gateway is read-only.</translation>
        </message>
        <message>
            <source>Refused: %1 is not in this connection&apos;s write allowlist.</source>
            <translation>Refused: %1 is not in this connection&apos;s write allowlist.</translation>
        </message>
        <message>
            <source>Refused: a retained command would write again at every restart; publish commands without the retain flag.</source>
            <translation>Refused: a retained command would write again at every restart; publish commands without the retain flag.</translation>
        </message>
        <message>
            <source>Refused: a command longer than %1 bytes.</source>
            <translation>Refused: a command longer than %1 bytes.</translation>
        </message>
        <message>
            <source>Refused: %1 writes are already waiting on this connection.</source>
            <translation>Refused: %1 writes are already waiting on this connection.</translation>
        </message>
        <message>
            <source>Refused: no item &quot;%2&quot; on station &quot;%1&quot; (write the address as a watch table shows it, R100, and the station as 1 to 254).</source>
            <translation>Refused: no item &quot;%2&quot; on station &quot;%1&quot; (write the address as a watch table shows it, R100, and the station as 1 to 254).</translation>
        </message>
        <message>
            <source>Expired: the command is %1 s old (commands older than %2 s are not carried out); send it again.</source>
            <translation>Expired: the command is %1 s old (commands older than %2 s are not carried out); send it again.</translation>
        </message>
        <message>
            <source>Expired: the command waited at the broker while the gateway was away, up to %1 s (commands older than %2 s are not carried out); send it again.</source>
            <translation>Expired: the command waited at the broker while the gateway was away, up to %1 s (commands older than %2 s are not carried out); send it again.</translation>
        </message>
        <message>
            <source>Not carried out: the command waited at the broker while the gateway was away, for a time nobody knows; send it again, with &quot;time&quot; so that its age can be checked (at most %1 s).</source>
            <translation>Not carried out: the command waited at the broker while the gateway was away, for a time nobody knows; send it again, with &quot;time&quot; so that its age can be checked (at most %1 s).</translation>
        </message>
        <message>
            <source>&quot;time&quot; must be a date and time in ISO 8601 with its offset (2026-11-27T10:15:00.000Z), not &quot;%1&quot;.</source>
            <translation>&quot;time&quot; must be a date and time in ISO 8601 with its offset (2026-11-27T10:15:00.000Z), not &quot;%1&quot;.</translation>
        </message>
        <message>
            <source>written</source>
            <translation>written</translation>
        </message>
        <message>
            <source>Ignored a command on %1: not an item of this connection.</source>
            <translation>Ignored a command on %1: not an item of this connection.</translation>
        </message>
        <message>
            <source>write station %1 %2 = &quot;%3&quot; (id &quot;%4&quot;): %5</source>
            <translation>write station %1 %2 = &quot;%3&quot; (id &quot;%4&quot;): %5</translation>
        </message>
        <message>
            <source>PLC link %1: %2</source>
            <translation>PLC link %1: %2</translation>
        </message>
        <message>
            <source>PLC link %1</source>
            <translation>PLC link %1</translation>
        </message>
        <message>
            <source>broker %1 connected</source>
            <translation>broker %1 connected</translation>
        </message>
        <message>
            <source>broker down: %1</source>
            <translation>broker down: %1</translation>
        </message>
        <message>
            <source>started: %1 {1:item|items} from %2, broker %3</source>
            <translation>started: %1 {1:item|items} from %2, broker %3</translation>
        </message>
        <message>
            <source>stopped (status offline)</source>
            <translation>stopped (status offline)</translation>
        </message>
        <message>
            <source>reloading %1: changed connections restart, the others keep running</source>
            <translation>reloading %1: changed connections restart, the others keep running</translation>
        </message>
        <message>
            <source>not reloaded, the running configuration stays: %1: %2</source>
            <translation>not reloaded, the running configuration stays: %1: %2</translation>
        </message>
        <message>
            <source>reloaded</source>
            <translation>reloaded</translation>
        </message>
        <message>
            <source>Passed with remark</source>
            <translation>Passed with remark</translation>
        </message>
        <message>
            <source>Deferred</source>
            <translation>Deferred</translation>
        </message>
        <message>
            <source>Not applicable</source>
            <translation>Not applicable</translation>
        </message>
        <message>
            <source>%1 %: %2</source>
            <translation>%1 %: %2</translation>
        </message>
        <message>
            <source>%1 %: found %2, left %3</source>
            <translation>%1 %: found %2, left %3</translation>
        </message>
        <message>
            <source>%1 %: %2, expected %3</source>
            <translation>%1 %: %2, expected %3</translation>
        </message>
        <message>
            <source>%1 (tolerance %2)</source>
            <translation>%1 (tolerance %2)</translation>
        </message>
        <message>
            <source>%1 has no expected values: give its scale (raw and engineering low and high) in the plan before it can pass</source>
            <translation>%1 has no expected values: give its scale (raw and engineering low and high) in the plan before it can pass</translation>
        </message>
        <message>
            <source>The checkout is not running: start it first. Nothing was forced.</source>
            <translation>The checkout is not running: start it first. Nothing was forced.</translation>
        </message>
        <message>
            <source>%1 is not a point of the checkout</source>
            <translation>%1 is not a point of the checkout</translation>
        </message>
        <message>
            <source>%1 is not an analog point</source>
            <translation>%1 is not an analog point</translation>
        </message>
        <message>
            <source>%1: &quot;passed with remark&quot; needs the remark</source>
            <translation>%1: &quot;passed with remark&quot; needs the remark</translation>
        </message>
        <message>
            <source>%1: &quot;deferred&quot; needs the reason</source>
            <translation>%1: &quot;deferred&quot; needs the reason</translation>
        </message>
        <message>
            <source>%1 cannot pass clean: %2 changed while it was tested (crossed wiring?). Re-test it, or pass it with a remark.</source>
            <translation>%1 cannot pass clean: %2 changed while it was tested (crossed wiring?). Re-test it, or pass it with a remark.</translation>
        </message>
        <message>
            <source>%1 passes or fails by what is read: read it at each check</source>
            <translation>%1 passes or fails by what is read: read it at each check</translation>
        </message>
        <message>
            <source>%1 has no check at %2 %</source>
            <translation>%1 has no check at %2 %</translation>
        </message>
        <message>
            <source>%1 at %2 %: read the value as found before the value as left</source>
            <translation>%1 at %2 %: read the value as found before the value as left</translation>
        </message>
        <message>
            <source>%1 still fails: re-test it before its punch item is closed out</source>
            <translation>%1 still fails: re-test it before its punch item is closed out</translation>
        </message>
        <message>
            <source>%1 is not on the punch list</source>
            <translation>%1 is not on the punch list</translation>
        </message>
        <message>
            <source>The PLC refuses %1 (%2): %3 {3:point|points} to take out of the plan. Nothing was forced.</source>
            <translation>The PLC refuses %1 (%2): %3 {3:point|points} to take out of the plan. Nothing was forced.</translation>
        </message>
        <message>
            <source>%1 are read again</source>
            <translation>%1 are read again</translation>
        </message>
        <message>
            <source>checks &quot;%1&quot;: per cents from 0 to 100 separated by &quot;/&quot;</source>
            <translation>checks &quot;%1&quot;: per cents from 0 to 100 separated by &quot;/&quot;</translation>
        </message>
        <message>
            <source>checkout file version %1 is not supported (this program reads 1 to %2)</source>
            <translation>checkout file version %1 is not supported (this program reads 1 to %2)</translation>
        </message>
        <message>
            <source>info</source>
            <translation>info</translation>
        </message>
        <message>
            <source>point %1 (%2)</source>
            <translation>point %1 (%2)</translation>
        </message>
        <message>
            <source>earlier attempt %1</source>
            <translation>earlier attempt %1</translation>
        </message>
        <message>
            <source>reading %1</source>
            <translation>reading %1</translation>
        </message>
        <message>
            <source>scale</source>
            <translation>scale</translation>
        </message>
        <message>
            <source>punch</source>
            <translation>punch</translation>
        </message>
        <message>
            <source>&quot;%1&quot; cannot be &quot;%2&quot;</source>
            <translation>&quot;%1&quot; cannot be &quot;%2&quot;</translation>
        </message>
        <message>
            <source>%1 {1:point|points}: %2 passed, %3 passed with remark, %4 failed, %5 deferred, %6 not applicable, %7 untested.</source>
            <translation>%1 {1:point|points}: %2 passed, %3 passed with remark, %4 failed, %5 deferred, %6 not applicable, %7 untested.</translation>
        </message>
        <message>
            <source>Punch list</source>
            <translation>Punch list</translation>
        </message>
        <message>
            <source>The punch list is empty: no point failed or was deferred.</source>
            <translation>The punch list is empty: no point failed or was deferred.</translation>
        </message>
        <message>
            <source>Attempts</source>
            <translation>Attempts</translation>
        </message>
        <message>
            <source>Owner</source>
            <translation>Owner</translation>
        </message>
        <message>
            <source>State</source>
            <translation>State</translation>
        </message>
        <message>
            <source>open</source>
            <translation>open</translation>
        </message>
        <message>
            <source>closed %1 by %2</source>
            <translation>closed %1 by %2</translation>
        </message>
        <message>
            <source>Document</source>
            <translation>Document</translation>
        </message>
        <message>
            <source>Revision</source>
            <translation>Revision</translation>
        </message>
        <message>
            <source>Name the engineer who records the results: the report says who tested each point.</source>
            <translation>Name the engineer who records the results: the report says who tested each point.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendHistory</name>
        <message numerus="yes">
            <source>%n value(s) exported to %1.</source>
            <translation>
                <numerusform>%n value exported to %1.</numerusform>
                <numerusform>%n values exported to %1.</numerusform>
            </translation>
        </message>
        <message>
            <source>History: %1</source>
            <translation>History: %1</translation>
        </message>
        <message>
            <source>Export Range to CSV</source>
            <translation>Export Range to CSV</translation>
        </message>
        <message>
            <source>None of the trend&apos;s items is recorded in the history.</source>
            <translation>None of the trend&apos;s items is recorded in the history.</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>Cannot write %1: %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendNavigation</name>
        <message>
            <source>How much time the trend shows</source>
            <translation>How much time the trend shows</translation>
        </message>
        <message>
            <source>10 s</source>
            <translation>10 s</translation>
        </message>
        <message>
            <source>1 min</source>
            <translation>1 min</translation>
        </message>
        <message>
            <source>10 min</source>
            <translation>10 min</translation>
        </message>
        <message>
            <source>1 h</source>
            <translation>1 h</translation>
        </message>
        <message>
            <source>8 h</source>
            <translation>8 h</translation>
        </message>
        <message>
            <source>24 h</source>
            <translation>24 h</translation>
        </message>
        <message>
            <source>7 days</source>
            <translation>7 days</translation>
        </message>
        <message>
            <source>Custom…</source>
            <translation>Custom…</translation>
        </message>
        <message>
            <source>Scroll back in time (Shift+wheel over the chart too); Reset Zoom follows the present again</source>
            <translation>Scroll back in time (Shift+wheel over the chart too); Reset Zoom follows the present again</translation>
        </message>
        <message>
            <source>Custom Time Range</source>
            <translation>Custom Time Range</translation>
        </message>
        <message>
            <source>&amp;From:</source>
            <translation>&amp;From:</translation>
        </message>
        <message>
            <source>&amp;To:</source>
            <translation>&amp;To:</translation>
        </message>
        <message>
            <source>The end must come after the beginning.</source>
            <translation>The end must come after the beginning.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::UiText</name>
        <message>
            <source>bit</source>
            <translation>bit</translation>
        </message>
        <message>
            <source>unsigned</source>
            <translation>unsigned</translation>
        </message>
        <message>
            <source>signed</source>
            <translation>signed</translation>
        </message>
        <message>
            <source>hex</source>
            <translation>hex</translation>
        </message>
        <message>
            <source>binary</source>
            <translation>binary</translation>
        </message>
        <message>
            <source>BCD</source>
            <translation>BCD</translation>
        </message>
        <message>
            <source>float</source>
            <translation>float</translation>
        </message>
        <message>
            <source>ASCII</source>
            <translation>ASCII</translation>
        </message>
        <message>
            <source>double</source>
            <translation>double</translation>
        </message>
        <message>
            <source>input</source>
            <translation>input</translation>
        </message>
        <message>
            <source>output relay</source>
            <translation>output relay</translation>
        </message>
        <message>
            <source>internal relay</source>
            <translation>internal relay</translation>
        </message>
        <message>
            <source>step relay</source>
            <translation>step relay</translation>
        </message>
        <message>
            <source>timer contact</source>
            <translation>timer contact</translation>
        </message>
        <message>
            <source>counter contact</source>
            <translation>counter contact</translation>
        </message>
        <message>
            <source>inputs as 16-bit word</source>
            <translation>inputs as 16-bit word</translation>
        </message>
        <message>
            <source>outputs as 16-bit word</source>
            <translation>outputs as 16-bit word</translation>
        </message>
        <message>
            <source>internal relays as 16-bit word</source>
            <translation>internal relays as 16-bit word</translation>
        </message>
        <message>
            <source>step relays as 16-bit word</source>
            <translation>step relays as 16-bit word</translation>
        </message>
        <message>
            <source>timer contacts as 16-bit word</source>
            <translation>timer contacts as 16-bit word</translation>
        </message>
        <message>
            <source>counter contacts as 16-bit word</source>
            <translation>counter contacts as 16-bit word</translation>
        </message>
        <message>
            <source>timer register</source>
            <translation>timer register</translation>
        </message>
        <message>
            <source>counter register</source>
            <translation>counter register</translation>
        </message>
        <message>
            <source>data register</source>
            <translation>data register</translation>
        </message>
        <message>
            <source>file register</source>
            <translation>file register</translation>
        </message>
        <message>
            <source>inputs as 32-bit word</source>
            <translation>inputs as 32-bit word</translation>
        </message>
        <message>
            <source>outputs as 32-bit word</source>
            <translation>outputs as 32-bit word</translation>
        </message>
        <message>
            <source>internal relays as 32-bit word</source>
            <translation>internal relays as 32-bit word</translation>
        </message>
        <message>
            <source>step relays as 32-bit word</source>
            <translation>step relays as 32-bit word</translation>
        </message>
        <message>
            <source>timer contacts as 32-bit word</source>
            <translation>timer contacts as 32-bit word</translation>
        </message>
        <message>
            <source>counter contacts as 32-bit word</source>
            <translation>counter contacts as 32-bit word</translation>
        </message>
        <message>
            <source>timer register pair</source>
            <translation>timer register pair</translation>
        </message>
        <message>
            <source>counter register pair</source>
            <translation>counter register pair</translation>
        </message>
        <message>
            <source>data register pair</source>
            <translation>data register pair</translation>
        </message>
        <message>
            <source>file register pair</source>
            <translation>file register pair</translation>
        </message>
        <message>
            <source>auto-detect</source>
            <translation>auto-detect</translation>
        </message>
        <message>
            <source>%1, %2</source>
            <extracomment>Link settings: medium (TCP 10.0.0.5:500, COM3 9600 7E1) and protocol.</extracomment>
            <translation>%1, %2</translation>
        </message>
        <message>
            <source>(no port)</source>
            <translation>(no port)</translation>
        </message>
        <message>
            <source>OS %1</source>
            <translation>OS %1</translation>
        </message>
        <message>
            <source>program %1 words</source>
            <translation>program %1 words</translation>
        </message>
        <message>
            <source>%1 I/O points</source>
            <translation>%1 I/O points</translation>
        </message>
        <message>
            <source>main unit type %1</source>
            <translation>main unit type %1</translation>
        </message>
        <message>
            <source>M series</source>
            <translation>M series</translation>
        </message>
        <message>
            <source>, </source>
            <comment>between the parts of a model text</comment>
            <translation>, </translation>
        </message>
    </context>
    <context>
        <name>Fatek::SavedConnection</name>
        <message>
            <source>MQTT gateway %1 on %2 (prefix %3)</source>
            <translation>MQTT gateway %1 on %2 (prefix %3)</translation>
        </message>
    </context>
    <context>
        <name>Fatek::DemoSimulator</name>
        <message>
            <source>Demo</source>
            <translation>Demo</translation>
        </message>
        <message>
            <source>Scan counter</source>
            <translation>Scan counter</translation>
        </message>
        <message>
            <source>counts ladder scans</source>
            <translation>counts ladder scans</translation>
        </message>
        <message>
            <source>Sine</source>
            <translation>Sine</translation>
        </message>
        <message>
            <source>±1000, 10 s period</source>
            <translation>±1000, 10 s period</translation>
        </message>
        <message>
            <source>Blink</source>
            <translation>Blink</translation>
        </message>
        <message>
            <source>1 Hz</source>
            <translation>1 Hz</translation>
        </message>
        <message>
            <source>Walking bit %1</source>
            <translation>Walking bit %1</translation>
        </message>
        <message>
            <source>one step per 250 ms</source>
            <translation>one step per 250 ms</translation>
        </message>
        <message>
            <source>Ramp</source>
            <translation>Ramp</translation>
        </message>
        <message>
            <source>0..99999, one step per 10 ms</source>
            <translation>0..99999, one step per 10 ms</translation>
        </message>
    </context>
    <context>
        <name>Fatek::DiscreteControlBatch</name>
        <message>
            <source>Disable</source>
            <translation>Disable</translation>
        </message>
        <message>
            <source>Enable</source>
            <translation>Enable</translation>
        </message>
        <message>
            <source>Set ON</source>
            <translation>Set ON</translation>
        </message>
        <message>
            <source>Reset OFF</source>
            <translation>Reset OFF</translation>
        </message>
        <message>
            <source>Disabled</source>
            <translation>Disabled</translation>
        </message>
        <message>
            <source>Enabled</source>
            <translation>Enabled</translation>
        </message>
        <message>
            <source>Set ON</source>
            <comment>past</comment>
            <extracomment>Past tense, as in "Set ON 3 points."</extracomment>
            <translation>Set ON</translation>
        </message>
        <message>
            <source>Reset OFF</source>
            <comment>past</comment>
            <extracomment>Past tense, as in "Reset OFF 3 points."</extracomment>
            <translation>Reset OFF</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>%1: %2 done, %3 failed — %4</source>
            <translation>%1: %2 done, %3 failed — %4</translation>
        </message>
        <message>
            <source> (and %1 more)</source>
            <translation> (and %1 more)</translation>
        </message>
        <message numerus="yes">
            <source>%1 %n points (%2, %3 … %4)</source>
            <extracomment>%1 is the action (Disable, Set ON...), %2..%4 the first, second and last point.</extracomment>
            <translation>
                <numerusform>%1 %n points (%2, %3 … %4)</numerusform>
                <numerusform>%1 %n points (%2, %3 … %4)</numerusform>
            </translation>
        </message>
        <message>
            <source>%1 1 point.</source>
            <extracomment>%1 is the past action (Disabled, Enabled, Set ON, Reset OFF).</extracomment>
            <translation>%1 1 point.</translation>
        </message>
        <message>
            <source>%1 %2 points.</source>
            <translation>%1 %2 points.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::DiscreteScan</name>
        <message>
            <source>“%1” is not a discrete type; use X, Y, M, S, T or C.</source>
            <translation>“%1” is not a discrete type; use X, Y, M, S, T or C.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::DiscreteTableModel</name>
        <message>
            <source>ON</source>
            <translation>ON</translation>
        </message>
        <message>
            <source>OFF</source>
            <translation>OFF</translation>
        </message>
        <message>
            <source>disabled (forced)</source>
            <translation>disabled (forced)</translation>
        </message>
        <message>
            <source>enabled</source>
            <translation>enabled</translation>
        </message>
        <message>
            <source>Point</source>
            <translation>Point</translation>
        </message>
        <message>
            <source>State</source>
            <translation>State</translation>
        </message>
        <message>
            <source>Forcing</source>
            <translation>Forcing</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>Name</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ForcedPointsView</name>
        <message>
            <source>Ranges:</source>
            <translation>Ranges:</translation>
        </message>
        <message>
            <source>Scan</source>
            <translation>Scan</translation>
        </message>
        <message>
            <source>Enable all</source>
            <translation>Enable all</translation>
        </message>
        <message>
            <source>Give every listed point back to the ladder</source>
            <translation>Give every listed point back to the ladder</translation>
        </message>
        <message>
            <source>Press Scan to list the forced points.</source>
            <translation>Press Scan to list the forced points.</translation>
        </message>
        <message>
            <source>No connection.</source>
            <translation>No connection.</translation>
        </message>
        <message>
            <source>Read-only (operator) mode: forcing is disabled.</source>
            <translation>Read-only (operator) mode: forcing is disabled.</translation>
        </message>
        <message>
            <source>Scanning %1 …</source>
            <translation>Scanning %1 …</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>Scan incomplete — %1</source>
            <translation>Scan incomplete — %1</translation>
        </message>
        <message>
            <source>%1 on %2?</source>
            <translation>%1 on %2?</translation>
        </message>
        <message>
            <source>Enable all forced points</source>
            <translation>Enable all forced points</translation>
        </message>
        <message>
            <source>Enable all cancelled; the points stay forced.</source>
            <translation>Enable all cancelled; the points stay forced.</translation>
        </message>
        <message>
            <source>All points of the PLC</source>
            <translation>All points of the PLC</translation>
        </message>
        <message>
            <source>Empty: every X Y M S T C point the PLC reports in its status. Or type ranges to scan, e.g. X0-255, Y0-255, M0-999</source>
            <translation>Empty: every X Y M S T C point the PLC reports in its status. Or type ranges to scan, e.g. X0-255, Y0-255, M0-999</translation>
        </message>
        <message>
            <source>Reading the PLC's sizes …</source>
            <translation>Reading the PLC's sizes …</translation>
        </message>
        <message>
            <source>The PLC did not report its sizes (%1): default ranges scanned.</source>
            <translation>The PLC did not report its sizes (%1): default ranges scanned.</translation>
        </message>
        <message>
            <source>The PLC did not report how many %1 it has: default ranges scanned for them.</source>
            <translation>The PLC did not report how many %1 it has: default ranges scanned for them.</translation>
        </message>
        <message>
            <source>Scanned %1: no forced points.</source>
            <translation>Scanned %1: no forced points.</translation>
        </message>
        <message>
            <source>Scanned %1: 1 forced point; enable it before leaving the site.</source>
            <translation>Scanned %1: 1 forced point; enable it before leaving the site.</translation>
        </message>
        <message>
            <source>Scanned %1: %2 forced points; enable them before leaving the site.</source>
            <translation>Scanned %1: %2 forced points; enable them before leaving the site.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ForcingPanel</name>
        <message>
            <source>Show</source>
            <translation>Show</translation>
        </message>
        <message>
            <source>Refresh every second</source>
            <translation>Refresh every second</translation>
        </message>
        <message>
            <source>Type:</source>
            <translation>Type:</translation>
        </message>
        <message>
            <source>From:</source>
            <translation>From:</translation>
        </message>
        <message>
            <source>Points:</source>
            <translation>Points:</translation>
        </message>
        <message>
            <source>Disable (force)</source>
            <translation>Disable (force)</translation>
        </message>
        <message>
            <source>Enable</source>
            <translation>Enable</translation>
        </message>
        <message>
            <source>Set ON</source>
            <translation>Set ON</translation>
        </message>
        <message>
            <source>Reset OFF</source>
            <translation>Reset OFF</translation>
        </message>
        <message>
            <source>Discretes</source>
            <translation>Discretes</translation>
        </message>
        <message>
            <source>Forced points</source>
            <translation>Forced points</translation>
        </message>
        <message>
            <source>No connection: choose a connection and a station.</source>
            <translation>No connection: choose a connection and a station.</translation>
        </message>
        <message>
            <source>Station %1 on “%2”</source>
            <translation>Station %1 on “%2”</translation>
        </message>
        <message>
            <source>Only X, Y, M, S, T and C points can be forced.</source>
            <translation>Only X, Y, M, S, T and C points can be forced.</translation>
        </message>
        <message>
            <source>Could not read: %1</source>
            <translation>Could not read: %1</translation>
        </message>
        <message>
            <source>Select the points first (Ctrl/Shift-click for several).</source>
            <translation>Select the points first (Ctrl/Shift-click for several).</translation>
        </message>
        <message>
            <source>%1 on %2?</source>
            <translation>%1 on %2?</translation>
        </message>
        <message>
            <source>Forcing</source>
            <translation>Forcing</translation>
        </message>
        <message>
            <source>Cancelled: nothing sent.</source>
            <translation>Cancelled: nothing sent.</translation>
        </message>
        <message>
            <source>%1 …</source>
            <translation>%1 …</translation>
        </message>
        <message>
            <source>Read-only (operator) mode: forcing is disabled.</source>
            <translation>Read-only (operator) mode: forcing is disabled.</translation>
        </message>
        <message>
            <source>%1 – %2</source>
            <translation>%1 – %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::LanguageMenu</name>
        <message>
            <source>&amp;Language</source>
            <translation>&amp;Language</translation>
        </message>
        <message>
            <source>System</source>
            <translation>System</translation>
        </message>
        <message>
            <source>Language</source>
            <translation>Language</translation>
        </message>
        <message>
            <source>The new language applies when FATEK Studio is started again.</source>
            <translation>The new language applies when FATEK Studio is started again.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::LinkStatusLabel</name>
        <message>
            <source>No connection</source>
            <translation>No connection</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message numerus="yes">
            <source> · %n failed attempt(s)</source>
            <translation>
                <numerusform> · %n failed attempt</numerusform>
                <numerusform> · %n failed attempts</numerusform>
            </translation>
        </message>
        <message>
            <source> · F5 reconnects now</source>
            <translation> · F5 reconnects now</translation>
        </message>
        <message>
            <source>%1: %2 · %3 req/s · %4 errors · RTT %5</source>
            <translation>%1: %2 · %3 req/s · %4 errors · RTT %5</translation>
        </message>
        <message>
            <source>%1 ms</source>
            <translation>%1 ms</translation>
        </message>
        <message>
            <source>%1: %2 · through the MQTT gateway</source>
            <translation>%1: %2 · through the MQTT gateway</translation>
        </message>
    </context>
    <context>
        <name>Fatek::LoopbackDialog</name>
        <message>
            <source>Loopback test</source>
            <translation>Loopback test</translation>
        </message>
        <message>
            <source>Text</source>
            <translation>Text</translation>
        </message>
        <message>
            <source>Hex bytes</source>
            <translation>Hex bytes</translation>
        </message>
        <message>
            <source>Generated pattern</source>
            <translation>Generated pattern</translation>
        </message>
        <message>
            <source> bytes</source>
            <translation> bytes</translation>
        </message>
        <message>
            <source>Test data:</source>
            <translation>Test data:</translation>
        </message>
        <message>
            <source>Repeat:</source>
            <translation>Repeat:</translation>
        </message>
        <message>
            <source> ms</source>
            <translation> ms</translation>
        </message>
        <message>
            <source>Interval:</source>
            <translation>Interval:</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>Start</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>Stop</translation>
        </message>
        <message>
            <source>Stopped: the target changed.</source>
            <translation>Stopped: the target changed.</translation>
        </message>
        <message>
            <source>Running %1 loopback tests of %2 bytes …</source>
            <translation>Running %1 loopback tests of %2 bytes …</translation>
        </message>
        <message>
            <source>Stopped after %1 runs.</source>
            <translation>Stopped after %1 runs.</translation>
        </message>
        <message>
            <source>%1  OK        %2 ms</source>
            <translation>%1  OK        %2 ms</translation>
        </message>
        <message>
            <source>%1  MISMATCH  %2 ms: got %3</source>
            <translation>%1  MISMATCH  %2 ms: got %3</translation>
        </message>
        <message>
            <source>%1  TIMEOUT   %2</source>
            <translation>%1  TIMEOUT   %2</translation>
        </message>
        <message>
            <source>%1  ERROR     %2</source>
            <translation>%1  ERROR     %2</translation>
        </message>
        <message>
            <source>Done.</source>
            <translation>Done.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::LoopbackStats</name>
        <message>
            <source>%1 runs: %2 OK, %3 mismatch, %4 timeout, %5 other errors</source>
            <translation>%1 runs: %2 OK, %3 mismatch, %4 timeout, %5 other errors</translation>
        </message>
        <message>
            <source> — round trip min %1 / mean %2 / max %3 / p99 %4 ms</source>
            <translation> — round trip min %1 / mean %2 / max %3 / p99 %4 ms</translation>
        </message>
    </context>
    <context>
        <name>Fatek::MainWindow</name>
        <message numerus="yes">
            <source>Closing %1: sending %n queued write(s) first (at most %2 s)…</source>
            <translation>
                <numerusform>Closing %1: sending %n queued write first (at most %2 s)…</numerusform>
                <numerusform>Closing %1: sending %n queued writes first (at most %2 s)…</numerusform>
            </translation>
        </message>
        <message>
            <source>Connections</source>
            <translation>Connections</translation>
        </message>
        <message>
            <source>Operator mode (read-only)</source>
            <translation>Operator mode (read-only)</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>%1: %2 (%3)</source>
            <translation>%1: %2 (%3)</translation>
        </message>
        <message>
            <source>&amp;File</source>
            <translation>&amp;File</translation>
        </message>
        <message>
            <source>Main</source>
            <translation>Main</translation>
        </message>
        <message>
            <source>&amp;New Connection…</source>
            <translation>&amp;New Connection…</translation>
        </message>
        <message>
            <source>&amp;Recent Connections</source>
            <translation>&amp;Recent Connections</translation>
        </message>
        <message>
            <source>&amp;Close Connection</source>
            <translation>&amp;Close Connection</translation>
        </message>
        <message>
            <source>New &amp;Watch Table</source>
            <translation>New &amp;Watch Table</translation>
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation>&amp;Quit</translation>
        </message>
        <message>
            <source>&amp;Watch</source>
            <translation>&amp;Watch</translation>
        </message>
        <message>
            <source>&amp;Add Items…</source>
            <translation>&amp;Add Items…</translation>
        </message>
        <message>
            <source>&amp;Pause Table</source>
            <translation>&amp;Pause Table</translation>
        </message>
        <message>
            <source>&amp;Close Table</source>
            <translation>&amp;Close Table</translation>
        </message>
        <message>
            <source>&amp;View</source>
            <translation>&amp;View</translation>
        </message>
        <message>
            <source>&amp;Tools</source>
            <translation>&amp;Tools</translation>
        </message>
        <message>
            <source>Connecting to %1 (%2)…</source>
            <translation>Connecting to %1 (%2)…</translation>
        </message>
        <message>
            <source>Watch %1</source>
            <translation>Watch %1</translation>
        </message>
        <message>
            <source>Rename Watch Table</source>
            <translation>Rename Watch Table</translation>
        </message>
        <message>
            <source>Name:</source>
            <translation>Name:</translation>
        </message>
        <message>
            <source>The demo simulator could not start: %1</source>
            <translation>The demo simulator could not start: %1</translation>
        </message>
        <message>
            <source>Demo PLC</source>
            <translation>Demo PLC</translation>
        </message>
        <message>
            <source>Starting the demo simulator…</source>
            <translation>Starting the demo simulator…</translation>
        </message>
        <message numerus="yes">
            <source>%n saved connection(s) could not be read (kept unchanged)</source>
            <translation>
                <numerusform>%n saved connection could not be read (kept unchanged)</numerusform>
                <numerusform>%n saved connections could not be read (kept unchanged)</numerusform>
            </translation>
        </message>
        <message>
            <source>Reconn&amp;ect Now</source>
            <translation>Reconn&amp;ect Now</translation>
        </message>
        <message>
            <source>Reconnecting %1 now…</source>
            <translation>Reconnecting %1 now…</translation>
        </message>
        <message>
            <source>Try the current connection again at once instead of waiting for the next attempt</source>
            <translation>Try the current connection again at once instead of waiting for the next attempt</translation>
        </message>
        <message>
            <source>%1 — %2, station %3</source>
            <translation>%1 — %2, station %3</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ClosedTables</name>
        <message>
            <source>&amp;Reopen Closed Table</source>
            <translation>&amp;Reopen Closed Table</translation>
        </message>
        <message numerus="yes">
            <source>Closed “%1” (%n row(s)): %2 reopens it.</source>
            <translation>
                <numerusform>Closed “%1” (%n row): %2 reopens it.</numerusform>
                <numerusform>Closed “%1” (%n rows): %2 reopens it.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Reopened “%1” (%n row(s)).</source>
            <translation>
                <numerusform>Reopened “%1” (%n row).</numerusform>
                <numerusform>Reopened “%1” (%n rows).</numerusform>
            </translation>
        </message>
        <message>
            <source>No watch table was closed</source>
            <translation>No watch table was closed</translation>
        </message>
        <message>
            <source>Open “%1” again, with its rows and settings</source>
            <translation>Open “%1” again, with its rows and settings</translation>
        </message>
    </context>
    <context>
        <name>Fatek::HelpMenu</name>
        <message>
            <source>&amp;Help</source>
            <translation>&amp;Help</translation>
        </message>
        <message>
            <source>&amp;User Guide</source>
            <translation>&amp;User Guide</translation>
        </message>
        <message>
            <source>&amp;Keyboard Shortcuts</source>
            <translation>&amp;Keyboard Shortcuts</translation>
        </message>
        <message>
            <source>&amp;About FATEK Studio</source>
            <translation>&amp;About FATEK Studio</translation>
        </message>
        <message>
            <source>About FATEK Studio</source>
            <translation>About FATEK Studio</translation>
        </message>
        <message>
            <source>FATEK Studio %1
Commissioning and monitoring tool for FATEK PLCs.</source>
            <translation>FATEK Studio %1
Commissioning and monitoring tool for FATEK PLCs.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ShortcutListDialog</name>
        <message>
            <source>Watch table</source>
            <translation>Watch table</translation>
        </message>
        <message>
            <source>Main window</source>
            <translation>Main window</translation>
        </message>
        <message>
            <source>Keyboard Shortcuts</source>
            <translation>Keyboard Shortcuts</translation>
        </message>
        <message>
            <source>Keys</source>
            <translation>Keys</translation>
        </message>
        <message>
            <source>Action</source>
            <translation>Action</translation>
        </message>
        <message>
            <source>Where</source>
            <translation>Where</translation>
        </message>
    </context>
    <context>
        <name>Fatek::UserGuideDialog</name>
        <message>
            <source>FATEK Studio User Guide</source>
            <translation>FATEK Studio User Guide</translation>
        </message>
        <message>
            <source>Back</source>
            <translation>Back</translation>
        </message>
        <message>
            <source>Forward</source>
            <translation>Forward</translation>
        </message>
        <message>
            <source>Contents</source>
            <translation>Contents</translation>
        </message>
        <message>
            <source>%1 is not part of the user guide built into the program.</source>
            <translation>%1 is not part of the user guide built into the program.</translation>
        </message>
        <message>
            <source>FATEK Studio User Guide — %1</source>
            <translation>FATEK Studio User Guide — %1</translation>
        </message>
    </context>
    <context>
        <name>Fatek::QuitQuestions</name>
        <message>
            <source>The watch list %1 has changes that are not saved.</source>
            <translation>The watch list %1 has changes that are not saved.</translation>
        </message>
        <message>
            <source>(untitled)</source>
            <translation>(untitled)</translation>
        </message>
        <message>
            <source>Data logging to %1 is running; quitting stops it.</source>
            <translation>Data logging to %1 is running; quitting stops it.</translation>
        </message>
        <message>
            <source>Quit FATEK Studio</source>
            <translation>Quit FATEK Studio</translation>
        </message>
        <message>
            <source>&amp;Save and Quit</source>
            <translation>&amp;Save and Quit</translation>
        </message>
        <message>
            <source>Quit &amp;Without Saving</source>
            <translation>Quit &amp;Without Saving</translation>
        </message>
        <message>
            <source>Stop Logging and &amp;Quit</source>
            <translation>Stop Logging and &amp;Quit</translation>
        </message>
        <message>
            <source>Writes not sent yet</source>
            <translation>Writes not sent yet</translation>
        </message>
        <message numerus="yes">
            <source>%n write(s) to the PLC have not been sent yet.</source>
            <translation>
                <numerusform>%n write to the PLC has not been sent yet.</numerusform>
                <numerusform>%n writes to the PLC have not been sent yet.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Wait for them (at most %n second(s)), or drop them? Dropped writes never reach the PLC.</source>
            <translation>
                <numerusform>Wait for them (at most %n second), or drop them? Dropped writes never reach the PLC.</numerusform>
                <numerusform>Wait for them (at most %n seconds), or drop them? Dropped writes never reach the PLC.</numerusform>
            </translation>
        </message>
        <message>
            <source>&amp;Wait and Quit</source>
            <translation>&amp;Wait and Quit</translation>
        </message>
        <message>
            <source>&amp;Drop and Quit</source>
            <translation>&amp;Drop and Quit</translation>
        </message>
        <message numerus="yes">
            <source>Sending %n queued write(s) before quitting (at most %1 s)…</source>
            <translation>
                <numerusform>Sending %n queued write before quitting (at most %1 s)…</numerusform>
                <numerusform>Sending %n queued writes before quitting (at most %1 s)…</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>Fatek::OperatorMode</name>
        <message>
            <source>&amp;Operator Mode (Read-Only)</source>
            <translation>&amp;Operator Mode (Read-Only)</translation>
        </message>
        <message>
            <source>Operator Mode Pass&amp;word…</source>
            <translation>Operator Mode Pass&amp;word…</translation>
        </message>
        <message>
            <source>Started with --read-only: operator mode stays on until the program is restarted without it.</source>
            <translation>Started with --read-only: operator mode stays on until the program is restarted without it.</translation>
        </message>
        <message>
            <source>Operator-mode password:</source>
            <translation>Operator-mode password:</translation>
        </message>
        <message>
            <source>Wrong operator-mode password: operator mode stays on.</source>
            <translation>Wrong operator-mode password: operator mode stays on.</translation>
        </message>
        <message>
            <source>Leave operator mode? Writes, forcing, RUN/STOP and raw frames will reach the PLC again.</source>
            <translation>Leave operator mode? Writes, forcing, RUN/STOP and raw frames will reach the PLC again.</translation>
        </message>
        <message>
            <source>Operator mode on: the PLC is read-only.</source>
            <translation>Operator mode on: the PLC is read-only.</translation>
        </message>
        <message>
            <source>Operator mode off.</source>
            <translation>Operator mode off.</translation>
        </message>
        <message>
            <source>Operator Mode</source>
            <translation>Operator Mode</translation>
        </message>
        <message>
            <source>New operator-mode password (empty: none):</source>
            <translation>New operator-mode password (empty: none):</translation>
        </message>
        <message>
            <source>Repeat the password:</source>
            <translation>Repeat the password:</translation>
        </message>
        <message>
            <source>The passwords differ: nothing changed.</source>
            <translation>The passwords differ: nothing changed.</translation>
        </message>
        <message>
            <source>Operator-mode password removed.</source>
            <translation>Operator-mode password removed.</translation>
        </message>
        <message>
            <source>Operator-mode password set.</source>
            <translation>Operator-mode password set.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::PlcControlPanel</name>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>PLC status</source>
            <translation>PLC status</translation>
        </message>
        <message>
            <source>RUN</source>
            <translation>RUN</translation>
        </message>
        <message>
            <source>Battery low</source>
            <translation>Battery low</translation>
        </message>
        <message>
            <source>Ladder checksum error</source>
            <translation>Ladder checksum error</translation>
        </message>
        <message>
            <source>Memory card / ROM pack</source>
            <translation>Memory card / ROM pack</translation>
        </message>
        <message>
            <source>Watchdog error</source>
            <translation>Watchdog error</translation>
        </message>
        <message>
            <source>ID set</source>
            <translation>ID set</translation>
        </message>
        <message>
            <source>Emergency stop</source>
            <translation>Emergency stop</translation>
        </message>
        <message>
            <source>STOP</source>
            <translation>STOP</translation>
        </message>
        <message>
            <source>Refresh</source>
            <translation>Refresh</translation>
        </message>
        <message>
            <source>Detail status (53)</source>
            <translation>Detail status (53)</translation>
        </message>
        <message>
            <source>Model:</source>
            <translation>Model:</translation>
        </message>
        <message>
            <source>I/O points:</source>
            <translation>I/O points:</translation>
        </message>
        <message>
            <source>OS version:</source>
            <translation>OS version:</translation>
        </message>
        <message>
            <source>Program size:</source>
            <translation>Program size:</translation>
        </message>
        <message>
            <source>Digital inputs / outputs:</source>
            <translation>Digital inputs / outputs:</translation>
        </message>
        <message>
            <source>Analog inputs / outputs:</source>
            <translation>Analog inputs / outputs:</translation>
        </message>
        <message>
            <source>M / S / L relays:</source>
            <translation>M / S / L relays:</translation>
        </message>
        <message>
            <source>R / D registers:</source>
            <translation>R / D registers:</translation>
        </message>
        <message>
            <source>Timers / counters:</source>
            <translation>Timers / counters:</translation>
        </message>
        <message>
            <source>Raw bytes:</source>
            <translation>Raw bytes:</translation>
        </message>
        <message>
            <source>No connection: choose a connection and a station.</source>
            <translation>No connection: choose a connection and a station.</translation>
        </message>
        <message>
            <source>Station %1 on “%2”</source>
            <translation>Station %1 on “%2”</translation>
        </message>
        <message>
            <source>Read-only (operator) mode: RUN/STOP is disabled.</source>
            <translation>Read-only (operator) mode: RUN/STOP is disabled.</translation>
        </message>
        <message>
            <source>Put %1 into %2?</source>
            <translation>Put %1 into %2?</translation>
        </message>
        <message>
            <source>PLC %1</source>
            <translation>PLC %1</translation>
        </message>
        <message>
            <source>%1 not sent: cancelled.</source>
            <translation>%1 not sent: cancelled.</translation>
        </message>
        <message>
            <source>Sending %1…</source>
            <translation>Sending %1…</translation>
        </message>
        <message>
            <source>%1 accepted by station %2.</source>
            <translation>%1 accepted by station %2.</translation>
        </message>
        <message>
            <source>%1 refused: %2</source>
            <translation>%1 refused: %2</translation>
        </message>
        <message>
            <source>Status unknown: %1</source>
            <translation>Status unknown: %1</translation>
        </message>
        <message>
            <source>the PLC sent no status bytes.</source>
            <translation>the PLC sent no status bytes.</translation>
        </message>
        <message>
            <source>Status read at %1.</source>
            <translation>Status read at %1.</translation>
        </message>
        <message>
            <source>Not available: %1</source>
            <translation>Not available: %1</translation>
        </message>
        <message>
            <source>Mode unknown</source>
            <translation>Mode unknown</translation>
        </message>
        <message>
            <source>(no bytes)</source>
            <translation>(no bytes)</translation>
        </message>
        <message>
            <source>not documented for the binary protocol (see raw bytes)</source>
            <translation>not documented for the binary protocol (see raw bytes)</translation>
        </message>
        <message>
            <source>main unit MA/MU</source>
            <translation>main unit MA/MU</translation>
        </message>
        <message>
            <source>main unit MC</source>
            <translation>main unit MC</translation>
        </message>
        <message>
            <source>main unit type %1</source>
            <translation>main unit type %1</translation>
        </message>
        <message>
            <source>code %1</source>
            <translation>code %1</translation>
        </message>
        <message>
            <source>code 0x%1</source>
            <translation>code 0x%1</translation>
        </message>
        <message>
            <source>%1 words</source>
            <translation>%1 words</translation>
        </message>
        <message>
            <source>The link is %1: RUN/STOP waits for it to connect.</source>
            <translation>The link is %1: RUN/STOP waits for it to connect.</translation>
        </message>
        <message>
            <source>M series (the unit does not report its type)</source>
            <translation>M series (the unit does not report its type)</translation>
        </message>
        <message>
            <source>not reported</source>
            <translation>not reported</translation>
        </message>
    </context>
    <context>
        <name>Fatek::RawConsole</name>
        <message>
            <source>All directions</source>
            <translation>All directions</translation>
        </message>
        <message>
            <source>Sent</source>
            <translation>Sent</translation>
        </message>
        <message>
            <source>Received</source>
            <translation>Received</translation>
        </message>
        <message>
            <source>Events</source>
            <translation>Events</translation>
        </message>
        <message>
            <source>All stations</source>
            <translation>All stations</translation>
        </message>
        <message>
            <source>Station </source>
            <translation>Station </translation>
        </message>
        <message>
            <source>All commands</source>
            <translation>All commands</translation>
        </message>
        <message>
            <source>Errors only</source>
            <translation>Errors only</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
        <message>
            <source>Clear</source>
            <translation>Clear</translation>
        </message>
        <message>
            <source>Copy</source>
            <translation>Copy</translation>
        </message>
        <message>
            <source>Save…</source>
            <translation>Save…</translation>
        </message>
        <message>
            <source>No connection: choose a connection to see its traffic.</source>
            <translation>No connection: choose a connection to see its traffic.</translation>
        </message>
        <message>
            <source>Traffic of “%1” (sending to station %2)</source>
            <translation>Traffic of “%1” (sending to station %2)</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Resume</translation>
        </message>
        <message>
            <source>Paused: new frames are kept in the log and shown on Resume.</source>
            <translation>Paused: new frames are kept in the log and shown on Resume.</translation>
        </message>
        <message>
            <source>%1 older frames were dropped from the log while paused.</source>
            <translation>%1 older frames were dropped from the log while paused.</translation>
        </message>
        <message>
            <source>Older frames were not kept while the console was closed; the newest are shown.</source>
            <translation>Older frames were not kept while the console was closed; the newest are shown.</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>Cannot write %1: %2</translation>
        </message>
        <message>
            <source>Save traffic</source>
            <translation>Save traffic</translation>
        </message>
        <message>
            <source>Tab-separated text (*.tsv *.txt)</source>
            <translation>Tab-separated text (*.tsv *.txt)</translation>
        </message>
        <message>
            <source>Saved to %1.</source>
            <translation>Saved to %1.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::RawSendBar</name>
        <message>
            <source>Hex</source>
            <translation>Hex</translation>
        </message>
        <message>
            <source>ASCII</source>
            <translation>ASCII</translation>
        </message>
        <message>
            <source>Send</source>
            <translation>Send</translation>
        </message>
        <message>
            <source>No connection.</source>
            <translation>No connection.</translation>
        </message>
        <message>
            <source>Add STX, LRC, ETX (FACON)</source>
            <translation>Add STX, LRC, ETX (FACON)</translation>
        </message>
        <message>
            <source>Add header, length, CRC (binary)</source>
            <translation>Add header, length, CRC (binary)</translation>
        </message>
        <message>
            <source>body in hex, e.g. 30 31 34 30</source>
            <translation>body in hex, e.g. 30 31 34 30</translation>
        </message>
        <message>
            <source>body, e.g. 014603R00012</source>
            <translation>body, e.g. 014603R00012</translation>
        </message>
        <message>
            <source>payload, e.g. 01 46 03 52 00 0C</source>
            <translation>payload, e.g. 01 46 03 52 00 0C</translation>
        </message>
        <message>
            <source>payload as ASCII</source>
            <translation>payload as ASCII</translation>
        </message>
        <message>
            <source>whole frame in hex, e.g. 02 30 31 34 30 43 37 03</source>
            <translation>whole frame in hex, e.g. 02 30 31 34 30 43 37 03</translation>
        </message>
        <message>
            <source>whole frame, e.g. &lt;STX&gt;0140C7&lt;ETX&gt;</source>
            <translation>whole frame, e.g. &lt;STX&gt;0140C7&lt;ETX&gt;</translation>
        </message>
        <message>
            <source>an unrecognized frame</source>
            <translation>an unrecognized frame</translation>
        </message>
        <message>
            <source>Send %1 (%2) on %3? It may change the PLC.</source>
            <translation>Send %1 (%2) on %3? It may change the PLC.</translation>
        </message>
        <message>
            <source>Send raw frame</source>
            <translation>Send raw frame</translation>
        </message>
        <message>
            <source>Cancelled: nothing sent.</source>
            <translation>Cancelled: nothing sent.</translation>
        </message>
        <message>
            <source>Sending %1
waiting for the answer …</source>
            <translation>Sending %1
waiting for the answer …</translation>
        </message>
        <message>
            <source>Not sent: %1
%2</source>
            <translation>Not sent: %1
%2</translation>
        </message>
        <message>
            <source>Sent    %1</source>
            <translation>Sent    %1</translation>
        </message>
        <message>
            <source>%1
Failed  %2</source>
            <translation>%1
Failed  %2</translation>
        </message>
        <message>
            <source>%1
Answer  %2
        %3
Meaning %4</source>
            <translation>%1
Answer  %2
        %3
Meaning %4</translation>
        </message>
        <message>
            <source>%1 (command %2) to station %3</source>
            <translation>%1 (command %2) to station %3</translation>
        </message>
        <message>
            <source>unknown command %1 to station %2</source>
            <translation>unknown command %1 to station %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::StatusIndicator</name>
        <message>
            <source>on</source>
            <translation>on</translation>
        </message>
        <message>
            <source>off</source>
            <translation>off</translation>
        </message>
        <message>
            <source>unknown</source>
            <translation>unknown</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TableLogger</name>
        <message>
            <source>No watch table to log.</source>
            <translation>No watch table to log.</translation>
        </message>
        <message>
            <source>removed from the table</source>
            <translation>removed from the table</translation>
        </message>
        <message>
            <source>format changed</source>
            <translation>format changed</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ToolConfirmation</name>
        <message>
            <source>station %1 on “%2”</source>
            <extracomment>How every question names its target: station 1 on “Line 3 (TCP 10.0.0.5:500)”.</extracomment>
            <translation>station %1 on “%2”</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ProgramTransferDialog</name>
        <message>
            <source>STOP: %1</source>
            <translation>STOP: %1</translation>
        </message>
        <message>
            <source>%1 RUN: %2</source>
            <translation>%1 RUN: %2</translation>
        </message>
        <message>
            <source>Program Backup / Restore</source>
            <translation>Program Backup / Restore</translation>
        </message>
        <message>
            <source>&amp;Back Up to File…</source>
            <translation>&amp;Back Up to File…</translation>
        </message>
        <message>
            <source>Read the PLC's program (every page) and save it in a file</source>
            <translation>Read the PLC's program (every page) and save it in a file</translation>
        </message>
        <message>
            <source>&amp;Restore from File…</source>
            <translation>&amp;Restore from File…</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancel</translation>
        </message>
        <message>
            <source>Stop after the page in progress</source>
            <translation>Stop after the page in progress</translation>
        </message>
        <message>
            <source>Program backups (*.fprog *.json);;All files (*)</source>
            <translation>Program backups (*.fprog *.json);;All files (*)</translation>
        </message>
        <message>
            <source>Back Up the PLC Program</source>
            <translation>Back Up the PLC Program</translation>
        </message>
        <message>
            <source>Restore a PLC Program</source>
            <translation>Restore a PLC Program</translation>
        </message>
        <message>
            <source>The PLC at %1 is in RUN. A program can only be written in STOP.

Switch the PLC to STOP now?</source>
            <translation>The PLC at %1 is in RUN. A program can only be written in STOP.

Switch the PLC to STOP now?</translation>
        </message>
        <message>
            <source>Restore Program</source>
            <translation>Restore Program</translation>
        </message>
        <message>
            <source>Not restored: the PLC stays in RUN. Nothing was written.</source>
            <translation>Not restored: the PLC stays in RUN. Nothing was written.</translation>
        </message>
        <message>
            <source>STOP failed: %1</source>
            <translation>STOP failed: %1</translation>
        </message>
        <message>
            <source>%1 The PLC is in RUN.</source>
            <translation>%1 The PLC is in RUN.</translation>
        </message>
        <message>
            <source>%1 RUN failed: %2 The PLC stays in STOP.</source>
            <translation>%1 RUN failed: %2 The PLC stays in STOP.</translation>
        </message>
        <message>
            <source>%1 The PLC stays in STOP: check the program before switching it to RUN.</source>
            <translation>%1 The PLC stays in STOP: check the program before switching it to RUN.</translation>
        </message>
        <message>
            <source>%1

The PLC at %2 was switched to STOP for the restore. Switch it back to RUN now? It runs its program as before.</source>
            <translation>%1

The PLC at %2 was switched to STOP for the restore. Switch it back to RUN now? It runs its program as before.</translation>
        </message>
        <message>
            <source>%1 The PLC stays in STOP: switch it to RUN when the machine is ready.</source>
            <translation>%1 The PLC stays in STOP: switch it to RUN when the machine is ready.</translation>
        </message>
        <message>
            <source>%1

Switch the PLC at %2 to RUN now? It starts the restored program.</source>
            <translation>%1

Switch the PLC at %2 to RUN now? It starts the restored program.</translation>
        </message>
        <message numerus="yes">
            <source>, about %n s left</source>
            <translation>
                <numerusform>, about %n s left</numerusform>
                <numerusform>, about %n s left</numerusform>
            </translation>
        </message>
        <message>
            <source>%1: %2 of %3 pages</source>
            <translation>%1: %2 of %3 pages</translation>
        </message>
        <message>
            <source>Writing %1 of %2 pages, verifying %3 of %2</source>
            <translation>Writing %1 of %2 pages, verifying %3 of %2</translation>
        </message>
        <message>
            <source>%1 Saved in %2.</source>
            <translation>%1 Saved in %2.</translation>
        </message>
        <message>
            <source>Write the program from %1 to the PLC at %2?

Backup: %3%4, %5 pages.
%6

The PLC's program is replaced; every page is read back and compared.</source>
            <translation>Write the program from %1 to the PLC at %2?

Backup: %3%4, %5 pages.
%6

The PLC's program is replaced; every page is read back and compared.</translation>
        </message>
        <message>
            <source>Not restored: nothing was written.</source>
            <translation>Not restored: nothing was written.</translation>
        </message>
        <message>
            <source>Read-only (operator) mode: restoring a program is disabled.</source>
            <translation>Read-only (operator) mode: restoring a program is disabled.</translation>
        </message>
        <message>
            <source>Write a program backup to the PLC (it must be in STOP)</source>
            <translation>Write a program backup to the PLC (it must be in STOP)</translation>
        </message>
        <message>
            <source>Operator mode: a backup can be made; restoring a program is disabled.</source>
            <translation>Operator mode: a backup can be made; restoring a program is disabled.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ToolDocks</name>
        <message>
            <source>PLC Control</source>
            <translation>PLC Control</translation>
        </message>
        <message>
            <source>Forcing</source>
            <translation>Forcing</translation>
        </message>
        <message>
            <source>Raw Console</source>
            <translation>Raw Console</translation>
        </message>
        <message>
            <source>&amp;Loopback Test…</source>
            <translation>&amp;Loopback Test…</translation>
        </message>
        <message>
            <source>Scan &amp;Stations…</source>
            <translation>Scan &amp;Stations…</translation>
        </message>
        <message>
            <source>Scan Stations: open a connection first.</source>
            <translation>Scan Stations: open a connection first.</translation>
        </message>
        <message>
            <source>Find the PLCs that answer on the current connection's link</source>
            <translation>Find the PLCs that answer on the current connection's link</translation>
        </message>
        <message>
            <source>&amp;Program Backup / Restore…</source>
            <translation>&amp;Program Backup / Restore…</translation>
        </message>
        <message>
            <source>Save the PLC's program in a file, or write a saved one back</source>
            <translation>Save the PLC's program in a file, or write a saved one back</translation>
        </message>
        <message>
            <source>Memory S&amp;napshot…</source>
            <translation>Memory S&amp;napshot…</translation>
        </message>
        <message>
            <source>Save, compare and restore element values of the current station</source>
            <translation>Save, compare and restore element values of the current station</translation>
        </message>
        <message>
            <source>Not available through an MQTT gateway connection: this tool needs a direct link to the PLC.</source>
            <translation>Not available through an MQTT gateway connection: this tool needs a direct link to the PLC.</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>I/O &amp;Checkout…</source>
            <translation>I/O &amp;Checkout…</translation>
        </message>
        <message>
            <source>Check every input, output and analog point of a machine and write the report</source>
            <translation>Check every input, output and analog point of a machine and write the report</translation>
        </message>
        <message>
            <source>%1 — %2, station %3</source>
            <translation>%1 — %2, station %3</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrafficLogModel</name>
        <message>
            <source>sent</source>
            <translation>sent</translation>
        </message>
        <message>
            <source>received</source>
            <translation>received</translation>
        </message>
        <message>
            <source>event</source>
            <translation>event</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>Time</translation>
        </message>
        <message>
            <source>Direction</source>
            <translation>Direction</translation>
        </message>
        <message>
            <source>Station</source>
            <translation>Station</translation>
        </message>
        <message>
            <source>Bytes (hex)</source>
            <translation>Bytes (hex)</translation>
        </message>
        <message>
            <source>ASCII</source>
            <translation>ASCII</translation>
        </message>
        <message>
            <source>Meaning</source>
            <translation>Meaning</translation>
        </message>
        <message>
            <source>Error</source>
            <translation>Error</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendChartView</name>
        <message>
            <source>no value</source>
            <translation>no value</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendLogging</name>
        <message>
            <source>Trend</source>
            <translation>Trend</translation>
        </message>
        <message>
            <source>&amp;Trend</source>
            <translation>&amp;Trend</translation>
        </message>
        <message>
            <source>Start &amp;Data Logging…</source>
            <translation>Start &amp;Data Logging…</translation>
        </message>
        <message>
            <source>Write every value of the current watch table to a CSV file with timestamps</source>
            <translation>Write every value of the current watch table to a CSV file with timestamps</translation>
        </message>
        <message>
            <source>Stop Data Lo&amp;gging</source>
            <translation>Stop Data Lo&amp;gging</translation>
        </message>
        <message>
            <source>Data logging stopped: %1</source>
            <translation>Data logging stopped: %1</translation>
        </message>
        <message>
            <source>Data Logging</source>
            <translation>Data Logging</translation>
        </message>
        <message>
            <source>Data logging stopped:
%1</source>
            <translation>Data logging stopped:
%1</translation>
        </message>
        <message>
            <source>No watch table to log.</source>
            <translation>No watch table to log.</translation>
        </message>
        <message>
            <source>Logging %1 to %2.</source>
            <translation>Logging %1 to %2.</translation>
        </message>
        <message numerus="yes">
            <source>Logging stopped: %n row(s) in %1.</source>
            <translation>
                <numerusform>Logging stopped: %n row in %1.</numerusform>
                <numerusform>Logging stopped: %n rows in %1.</numerusform>
            </translation>
        </message>
        <message>
            <source>Add items to a watch table first: logging writes the rows of the current table.</source>
            <translation>Add items to a watch table first: logging writes the rows of the current table.</translation>
        </message>
        <message>
            <source>Log Watch Table to CSV</source>
            <translation>Log Watch Table to CSV</translation>
        </message>
        <message numerus="yes">
            <source>Logging to %1 (%n row(s))</source>
            <translation>
                <numerusform>Logging to %1 (%n row)</numerusform>
                <numerusform>Logging to %1 (%n rows)</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendValueAxes</name>
        <message>
            <source>Bits</source>
            <translation>Bits</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Value</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendView</name>
        <message>
            <source>Time</source>
            <translation>Time</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
        <message>
            <source>Freeze the trend (no new points until resumed)</source>
            <translation>Freeze the trend (no new points until resumed)</translation>
        </message>
        <message>
            <source>Reset Zoom</source>
            <translation>Reset Zoom</translation>
        </message>
        <message>
            <source>Show the whole time window again and follow the present</source>
            <translation>Show the whole time window again and follow the present</translation>
        </message>
        <message>
            <source>Remove</source>
            <translation>Remove</translation>
        </message>
        <message>
            <source>Remove the selected item from the trend</source>
            <translation>Remove the selected item from the trend</translation>
        </message>
        <message>
            <source>&amp;Remove from Trend</source>
            <translation>&amp;Remove from Trend</translation>
        </message>
        <message>
            <source>Select rows in a watch table and choose "Add to Trend" from its context menu.</source>
            <translation>Select rows in a watch table and choose "Add to Trend" from its context menu.</translation>
        </message>
        <message>
            <source>Window:</source>
            <translation>Window:</translation>
        </message>
        <message>
            <source>%1 (%2)</source>
            <translation>%1 (%2)</translation>
        </message>
        <message>
            <source>No watch table row to trend.</source>
            <translation>No watch table row to trend.</translation>
        </message>
        <message>
            <source>%1 is already in the trend.</source>
            <translation>%1 is already in the trend.</translation>
        </message>
        <message>
            <source>%1 is shown as %2, which has no value to plot.</source>
            <translation>%1 is shown as %2, which has no value to plot.</translation>
        </message>
        <message>
            <source>%1 added to the trend.</source>
            <translation>%1 added to the trend.</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Resume</translation>
        </message>
        <message>
            <source>Station %1, %2</source>
            <translation>Station %1, %2</translation>
        </message>
        <message>
            <source>Separate Axes</source>
            <translation>Separate Axes</translation>
        </message>
        <message>
            <source>Give every item its own value axis (bits share one); off: one value axis for all items except bits</source>
            <translation>Give every item its own value axis (bits share one); off: one value axis for all items except bits</translation>
        </message>
        <message numerus="yes">
            <source>%n item(s) added to the trend.</source>
            <translation>
                <numerusform>%n item added to the trend.</numerusform>
                <numerusform>%n items added to the trend.</numerusform>
            </translation>
        </message>
        <message>
            <source>Drag a rectangle to zoom in, right-click to zoom out, wheel to zoom the time axis, Shift+wheel to scroll it</source>
            <translation>Drag a rectangle to zoom in, right-click to zoom out, wheel to zoom the time axis, Shift+wheel to scroll it</translation>
        </message>
        <message>
            <source>Export Range…</source>
            <translation>Export Range…</translation>
        </message>
        <message>
            <source>Write the recorded values of the items in the time range shown to a CSV file</source>
            <translation>Write the recorded values of the items in the time range shown to a CSV file</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchInput</name>
        <message>
            <source>Type an address such as R100, or a range such as R100..R163.</source>
            <translation>Type an address such as R100, or a range such as R100..R163.</translation>
        </message>
        <message>
            <source>"%1": %2</source>
            <translation>"%1": %2</translation>
        </message>
        <message>
            <source>Too many items at once: at most %1.</source>
            <translation>Too many items at once: at most %1.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchListDocument</name>
        <message>
            <source>&amp;Open Watch List…</source>
            <translation>&amp;Open Watch List…</translation>
        </message>
        <message>
            <source>&amp;Save Watch List…</source>
            <translation>&amp;Save Watch List…</translation>
        </message>
        <message>
            <source>&amp;Import CSV…</source>
            <translation>&amp;Import CSV…</translation>
        </message>
        <message>
            <source>Reopen Last Watch List at Start</source>
            <translation>Reopen Last Watch List at Start</translation>
        </message>
        <message>
            <source>The last watch list %1 cannot be loaded: %2</source>
            <translation>The last watch list %1 cannot be loaded: %2</translation>
        </message>
        <message>
            <source>Reopened %1.</source>
            <translation>Reopened %1.</translation>
        </message>
        <message>
            <source>Cannot open %1: %2</source>
            <translation>Cannot open %1: %2</translation>
        </message>
        <message>
            <source>Open Watch List</source>
            <translation>Open Watch List</translation>
        </message>
        <message>
            <source>Watch lists (*.json);;All files (*)</source>
            <translation>Watch lists (*.json);;All files (*)</translation>
        </message>
        <message>
            <source>%1 cannot be loaded:
%2</source>
            <translation>%1 cannot be loaded:
%2</translation>
        </message>
        <message>
            <source>Loaded %1.</source>
            <translation>Loaded %1.</translation>
        </message>
        <message>
            <source>Save Watch List</source>
            <translation>Save Watch List</translation>
        </message>
        <message>
            <source>Watch lists (*.json)</source>
            <translation>Watch lists (*.json)</translation>
        </message>
        <message>
            <source>Saved %1.</source>
            <translation>Saved %1.</translation>
        </message>
        <message>
            <source>Import CSV</source>
            <translation>Import CSV</translation>
        </message>
        <message>
            <source>CSV files (*.csv *.txt);;All files (*)</source>
            <translation>CSV files (*.csv *.txt);;All files (*)</translation>
        </message>
        <message>
            <source>%1 cannot be imported:
%2</source>
            <translation>%1 cannot be imported:
%2</translation>
        </message>
        <message>
            <source>Imported %1.</source>
            <translation>Imported %1.</translation>
        </message>
        <message>
            <source>Untitled</source>
            <translation>Untitled</translation>
        </message>
        <message>
            <source>%1 — Operator mode (read-only)</source>
            <translation>%1 — Operator mode (read-only)</translation>
        </message>
        <message>
            <source>Import Names and Co&amp;mments…</source>
            <translation>Import Names and Co&amp;mments…</translation>
        </message>
        <message>
            <source>Read the names and comments of addresses from the ladder project&apos;s comment/symbol list (CSV or tab-separated text)</source>
            <translation>Read the names and comments of addresses from the ladder project&apos;s comment/symbol list (CSV or tab-separated text)</translation>
        </message>
        <message>
            <source>%1 cannot be imported: %2</source>
            <translation>%1 cannot be imported: %2</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>Import Names and Comments</source>
            <translation>Import Names and Comments</translation>
        </message>
        <message>
            <source>Comment/symbol lists (*.csv *.txt *.tsv);;All files (*)</source>
            <translation>Comment/symbol lists (*.csv *.txt *.tsv);;All files (*)</translation>
        </message>
        <message>
            <source>The watch list %1 has changes that are not saved.</source>
            <translation>The watch list %1 has changes that are not saved.</translation>
        </message>
        <message>
            <source>(untitled)</source>
            <translation>(untitled)</translation>
        </message>
        <message>
            <source>Save them first?</source>
            <translation>Save them first?</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchTableModel</name>
        <message>
            <source>good</source>
            <translation>good</translation>
        </message>
        <message>
            <source>late</source>
            <translation>late</translation>
        </message>
        <message>
            <source>stale</source>
            <translation>stale</translation>
        </message>
        <message>
            <source>error</source>
            <translation>error</translation>
        </message>
        <message>
            <source>%1, words swapped</source>
            <translation>%1, words swapped</translation>
        </message>
        <message>
            <source>waiting</source>
            <translation>waiting</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>No value yet</source>
            <translation>No value yet</translation>
        </message>
        <message>
            <source>The gateway&apos;s name for this item; type a name to use your own.</source>
            <translation>The gateway&apos;s name for this item; type a name to use your own.</translation>
        </message>
        <message>
            <source>Click the box to toggle</source>
            <translation>Click the box to toggle</translation>
        </message>
        <message>
            <source>Double-click or F2 to write</source>
            <translation>Double-click or F2 to write</translation>
        </message>
        <message>
            <source>%1 .. %2 (%3 elements)</source>
            <translation>%1 .. %2 (%3 elements)</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>Name</translation>
        </message>
        <message>
            <source>Address</source>
            <translation>Address</translation>
        </message>
        <message>
            <source>Station</source>
            <translation>Station</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Value</translation>
        </message>
        <message>
            <source>Format</source>
            <translation>Format</translation>
        </message>
        <message>
            <source>Quality</source>
            <translation>Quality</translation>
        </message>
        <message>
            <source>Last update</source>
            <translation>Last update</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>Comment</translation>
        </message>
        <message>
            <source>Station must be a number from 1 to 254.</source>
            <translation>Station must be a number from 1 to 254.</translation>
        </message>
        <message>
            <source>Unknown format "%1".</source>
            <translation>Unknown format "%1".</translation>
        </message>
        <message>
            <source>no answer</source>
            <translation>no answer</translation>
        </message>
        <message>
            <source>No answer from station %1: check the station number, the PLC's power and the cable.</source>
            <translation>No answer from station %1: check the station number, the PLC's power and the cable.</translation>
        </message>
        <message>
            <source>Forced: disabled from the ladder, it keeps the value written to it (Tools ▸ Forcing lists and enables forced points).</source>
            <translation>Forced: disabled from the ladder, it keeps the value written to it (Tools ▸ Forcing lists and enables forced points).</translation>
        </message>
        <message>
            <source>%1 s</source>
            <translation>%1 s</translation>
        </message>
        <message>
            <source>%1 min</source>
            <translation>%1 min</translation>
        </message>
        <message>
            <source>%1 h</source>
            <translation>%1 h</translation>
        </message>
        <message>
            <source>%1, %2</source>
            <comment>quality, age of the value</comment>
            <translation>%1, %2</translation>
        </message>
        <message numerus="yes">
            <source>%n alarm(s) defined (Alarms… in the context menu, Ctrl+Shift+A)</source>
            <translation>
                <numerusform>%n alarm defined (Alarms… in the context menu, Ctrl+Shift+A)</numerusform>
                <numerusform>%n alarms defined (Alarms… in the context menu, Ctrl+Shift+A)</numerusform>
            </translation>
        </message>
        <message>
            <source>Recorded in the history (deadband %1, heartbeat %2 s)</source>
            <translation>Recorded in the history (deadband %1, heartbeat %2 s)</translation>
        </message>
        <message>
            <source>ON</source>
            <translation>ON</translation>
        </message>
        <message>
            <source>OFF</source>
            <translation>OFF</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchTableEdits</name>
        <message numerus="yes">
            <source>Add %n item(s)</source>
            <translation>
                <numerusform>Add %n item</numerusform>
                <numerusform>Add %n items</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Remove %n item(s)</source>
            <translation>
                <numerusform>Remove %n item</numerusform>
                <numerusform>Remove %n items</numerusform>
            </translation>
        </message>
        <message>
            <source>Move Up</source>
            <translation>Move Up</translation>
        </message>
        <message>
            <source>Move Down</source>
            <translation>Move Down</translation>
        </message>
        <message numerus="yes">
            <source>Move %n item(s)</source>
            <translation>
                <numerusform>Move %n item</numerusform>
                <numerusform>Move %n items</numerusform>
            </translation>
        </message>
        <message>
            <source>Edit %1</source>
            <translation>Edit %1</translation>
        </message>
        <message>
            <source>Set Format</source>
            <translation>Set Format</translation>
        </message>
        <message>
            <source>Alarms of %1</source>
            <translation>Alarms of %1</translation>
        </message>
        <message>
            <source>Record in History</source>
            <translation>Record in History</translation>
        </message>
        <message>
            <source>Stop Recording</source>
            <translation>Stop Recording</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchTableWidget</name>
        <message>
            <source>Watch</source>
            <translation>Watch</translation>
        </message>
        <message>
            <source>Add: R100, R100..R163, X0..X15 — Enter</source>
            <translation>Add: R100, R100..R163, X0..X15 — Enter</translation>
        </message>
        <message>
            <source>Add</source>
            <translation>Add</translation>
        </message>
        <message>
            <source>Connection this table polls through</source>
            <translation>Connection this table polls through</translation>
        </message>
        <message>
            <source> ms</source>
            <translation> ms</translation>
        </message>
        <message>
            <source>Poll interval of this table</source>
            <translation>Poll interval of this table</translation>
        </message>
        <message>
            <source>Polled at the intervals %1 is configured with</source>
            <translation>Polled at the intervals %1 is configured with</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
        <message>
            <source>Stop polling this table</source>
            <translation>Stop polling this table</translation>
        </message>
        <message>
            <source>Confirm writes</source>
            <translation>Confirm writes</translation>
        </message>
        <message>
            <source>Connection:</source>
            <translation>Connection:</translation>
        </message>
        <message>
            <source>Every</source>
            <translation>Every</translation>
        </message>
        <message>
            <source>polling paused</source>
            <translation>polling paused</translation>
        </message>
        <message>
            <source>link %1</source>
            <translation>link %1</translation>
        </message>
        <message>
            <source>link %1: %2</source>
            <translation>link %1: %2</translation>
        </message>
        <message>
            <source>no connection</source>
            <translation>no connection</translation>
        </message>
        <message numerus="yes">
            <source>Added %n item(s).</source>
            <translation>
                <numerusform>Added %n item.</numerusform>
                <numerusform>Added %n items.</numerusform>
            </translation>
        </message>
        <message>
            <source>Cannot paste: %1</source>
            <translation>Cannot paste: %1</translation>
        </message>
        <message numerus="yes">
            <source>Pasted %n item(s).</source>
            <translation>
                <numerusform>Pasted %n item.</numerusform>
                <numerusform>Pasted %n items.</numerusform>
            </translation>
        </message>
        <message>
            <source>%1 is connected again; %2 was not written.</source>
            <translation>%1 is connected again; %2 was not written.</translation>
        </message>
        <message numerus="yes">
            <source>Added %n item(s), each timer and counter contact with its current value (RT/RC) beside it.</source>
            <translation>
                <numerusform>Added %n item, each timer and counter contact with its current value (RT/RC) beside it.</numerusform>
                <numerusform>Added %n items, each timer and counter contact with its current value (RT/RC) beside it.</numerusform>
            </translation>
        </message>
        <message>
            <source>Filter: address, name or comment</source>
            <translation>Filter: address, name or comment</translation>
        </message>
        <message>
            <source>Show only the rows whose address, name or comment contains this text (Ctrl+F)</source>
            <translation>Show only the rows whose address, name or comment contains this text (Ctrl+F)</translation>
        </message>
        <message numerus="yes">
            <source>Copied %n row(s).</source>
            <translation>
                <numerusform>Copied %n row.</numerusform>
                <numerusform>Copied %n rows.</numerusform>
            </translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Resume</translation>
        </message>
        <message>
            <source>Poll this table again</source>
            <translation>Poll this table again</translation>
        </message>
        <message>
            <source>Rows move only in own order: clear the filter, choose Own Order.</source>
            <translation>Rows move only in own order: clear the filter, choose Own Order.</translation>
        </message>
        <message>
            <source>Operator mode is off; %1 was not written.</source>
            <translation>Operator mode is off; %1 was not written.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchTableWriter</name>
        <message>
            <source>%1 (station %2) = %3</source>
            <translation>%1 (station %2) = %3</translation>
        </message>
        <message>
            <source>Cannot write %1: the table has no connection.</source>
            <translation>Cannot write %1: the table has no connection.</translation>
        </message>
        <message>
            <source>Write %1 to the PLC on %2?</source>
            <translation>Write %1 to the PLC on %2?</translation>
        </message>
        <message>
            <source>Write Value</source>
            <translation>Write Value</translation>
        </message>
        <message>
            <source>Write of %1 cancelled.</source>
            <translation>Write of %1 cancelled.</translation>
        </message>
        <message>
            <source>Writing %1 …</source>
            <translation>Writing %1 …</translation>
        </message>
        <message>
            <source>Wrote %1.</source>
            <translation>Wrote %1.</translation>
        </message>
        <message>
            <source>Wrote %1. %2</source>
            <translation>Wrote %1. %2</translation>
        </message>
        <message>
            <source>Write of %1: %2</source>
            <translation>Write of %1: %2</translation>
        </message>
        <message>
            <source>Write of %1 failed: %2</source>
            <translation>Write of %1 failed: %2</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>Operator mode (read-only): %1 cannot be written.</source>
            <translation>Operator mode (read-only): %1 cannot be written.</translation>
        </message>
        <message>
            <source>New value for %1 (%2; hex as 0x1A or 1Ah):</source>
            <translation>New value for %1 (%2; hex as 0x1A or 1Ah):</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchTableActions</name>
        <message>
            <source>&amp;Write Value…</source>
            <translation>&amp;Write Value…</translation>
        </message>
        <message>
            <source>&amp;Swap Words</source>
            <translation>&amp;Swap Words</translation>
        </message>
        <message>
            <source>Low word first for 32- and 64-bit values (some HMIs store floats so)</source>
            <translation>Low word first for 32- and 64-bit values (some HMIs store floats so)</translation>
        </message>
        <message>
            <source>&amp;Copy Rows</source>
            <translation>&amp;Copy Rows</translation>
        </message>
        <message>
            <source>Address, name, value, format, quality and comment of the selected rows as tab-separated text</source>
            <translation>Address, name, value, format, quality and comment of the selected rows as tab-separated text</translation>
        </message>
        <message>
            <source>&amp;Paste Items</source>
            <translation>&amp;Paste Items</translation>
        </message>
        <message>
            <source>&amp;Remove</source>
            <translation>&amp;Remove</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>&amp;Undo</translation>
        </message>
        <message>
            <source>&amp;Redo</source>
            <translation>&amp;Redo</translation>
        </message>
        <message>
            <source>Move &amp;Up</source>
            <translation>Move &amp;Up</translation>
        </message>
        <message>
            <source>Move &amp;Down</source>
            <translation>Move &amp;Down</translation>
        </message>
        <message>
            <source>Own &amp;Order</source>
            <translation>Own &amp;Order</translation>
        </message>
        <message>
            <source>Show the rows in the order you gave them, not sorted</source>
            <translation>Show the rows in the order you gave them, not sorted</translation>
        </message>
        <message>
            <source>Set &amp;Format</source>
            <translation>Set &amp;Format</translation>
        </message>
        <message>
            <source>Add to &amp;Trend</source>
            <translation>Add to &amp;Trend</translation>
        </message>
        <message>
            <source>Plot the selected items over time in the trend view</source>
            <translation>Plot the selected items over time in the trend view</translation>
        </message>
    </context>
    <context>
        <name>main</name>
        <message>
            <source>Commissioning and monitoring tool for FATEK PLCs.</source>
            <translation>Commissioning and monitoring tool for FATEK PLCs.</translation>
        </message>
        <message>
            <source>Start the embedded PLC simulator (demo ladder) and watch it.</source>
            <translation>Start the embedded PLC simulator (demo ladder) and watch it.</translation>
        </message>
        <message>
            <source>Operator mode: no writes, RUN/STOP or forcing.</source>
            <translation>Operator mode: no writes, RUN/STOP or forcing.</translation>
        </message>
        <message>
            <source>Render the main window to a PNG file after startup and exit.</source>
            <translation>Render the main window to a PNG file after startup and exit.</translation>
        </message>
        <message>
            <source>file</source>
            <translation>file</translation>
        </message>
        <message>
            <source>With --screenshot: open a commissioning tool first (connection, control, forcing, console, loopback, program, snapshot, trend).</source>
            <translation>With --screenshot: open a commissioning tool first (connection, control, forcing, console, loopback, program, snapshot, trend).</translation>
        </message>
        <message>
            <source>name</source>
            <translation>name</translation>
        </message>
        <message>
            <source>User interface language for this run: en or zh_TW (default: the View &gt; Language choice, else the system's).</source>
            <translation>User interface language for this run: en or zh_TW (default: the View &gt; Language choice, else the system's).</translation>
        </message>
        <message>
            <source>code</source>
            <translation>code</translation>
        </message>
        <message>
            <source>Watch list to open (.json); with a link option its tables watch that connection.</source>
            <translation>Watch list to open (.json); with a link option its tables watch that connection.</translation>
        </message>
        <message>
            <source>Open a link by URL (tcp://HOST[:PORT], udp://HOST[:PORT], serial://PORT?baud=19200&amp;format=7E1) or by its name in links.conf (@line1).</source>
            <translation>Open a link by URL (tcp://HOST[:PORT], udp://HOST[:PORT], serial://PORT?baud=19200&amp;format=7E1) or by its name in links.conf (@line1).</translation>
        </message>
        <message>
            <source>Open a FATEK link over TCP (port 500 if not given).</source>
            <translation>Open a FATEK link over TCP (port 500 if not given).</translation>
        </message>
        <message>
            <source>Open a FATEK link over UDP (port 500 if not given).</source>
            <translation>Open a FATEK link over UDP (port 500 if not given).</translation>
        </message>
        <message>
            <source>Open a FATEK link on a serial line.</source>
            <translation>Open a FATEK link on a serial line.</translation>
        </message>
        <message>
            <source>With --serial: speed (9600).</source>
            <translation>With --serial: speed (9600).</translation>
        </message>
        <message>
            <source>With --serial: parity (E).</source>
            <translation>With --serial: parity (E).</translation>
        </message>
        <message>
            <source>With --serial: data bits (7).</source>
            <translation>With --serial: data bits (7).</translation>
        </message>
        <message>
            <source>With --serial: stop bits (1).</source>
            <translation>With --serial: stop bits (1).</translation>
        </message>
        <message>
            <source>Protocol on the link (auto).</source>
            <translation>Protocol on the link (auto).</translation>
        </message>
        <message>
            <source>Station number of the link (1).</source>
            <translation>Station number of the link (1).</translation>
        </message>
        <message>
            <source>Answer timeout per attempt (1000).</source>
            <translation>Answer timeout per attempt (1000).</translation>
        </message>
        <message>
            <source>Extra attempts after a timeout (2).</source>
            <translation>Extra attempts after a timeout (2).</translation>
        </message>
    </context>
    <context>
        <name>Fatek::Connection</name>
        <message>
            <source>%1, no answer from station %2</source>
            <translation>%1, no answer from station %2</translation>
        </message>
        <message>
            <source>station %1 rests until %2</source>
            <translation>station %1 rests until %2</translation>
        </message>
        <message>
            <source>RUN</source>
            <translation>RUN</translation>
        </message>
        <message>
            <source>STOP</source>
            <translation>STOP</translation>
        </message>
        <message>
            <source>M series</source>
            <translation>M series</translation>
        </message>
    </context>
    <context>
        <name>Fatek::StationScanDialog</name>
        <message>
            <source>Scan Stations</source>
            <translation>Scan Stations</translation>
        </message>
        <message>
            <source>Asks each station on “%1” for its status (command 40), one at a time, and lists who answers.</source>
            <translation>Asks each station on “%1” for its status (command 40), one at a time, and lists who answers.</translation>
        </message>
        <message>
            <source>No connection: open one first.</source>
            <translation>No connection: open one first.</translation>
        </message>
        <message>
            <source>to</source>
            <translation>to</translation>
        </message>
        <message>
            <source>Stations:</source>
            <translation>Stations:</translation>
        </message>
        <message>
            <source> ms</source>
            <translation> ms</translation>
        </message>
        <message>
            <source>How long each station has to answer (no retries). 100 ms suits 9600 baud and above; a modem or radio link needs more.</source>
            <translation>How long each station has to answer (no retries). 100 ms suits 9600 baud and above; a modem or radio link needs more.</translation>
        </message>
        <message>
            <source>Wait per station:</source>
            <translation>Wait per station:</translation>
        </message>
        <message>
            <source>&amp;Scan</source>
            <translation>&amp;Scan</translation>
        </message>
        <message>
            <source>&amp;Use Station</source>
            <translation>&amp;Use Station</translation>
        </message>
        <message>
            <source>Make the selected station the one the tools and new tables use</source>
            <translation>Make the selected station the one the tools and new tables use</translation>
        </message>
        <message>
            <source>Scanning stations %1 to %2 …</source>
            <translation>Scanning stations %1 to %2 …</translation>
        </message>
        <message>
            <source>Station %1 — %2</source>
            <translation>Station %1 — %2</translation>
        </message>
        <message>
            <source> (in use)</source>
            <translation> (in use)</translation>
        </message>
        <message>
            <source>No station answered. Check the cable, the baud rate and parity, and that the PLCs are powered.</source>
            <translation>No station answered. Check the cable, the baud rate and parity, and that the PLCs are powered.</translation>
        </message>
        <message numerus="yes">
            <source>%n station(s) answered.</source>
            <translation>
                <numerusform>%n station answered.</numerusform>
                <numerusform>%n stations answered.</numerusform>
            </translation>
        </message>
        <message>
            <source>“%1” now uses station %2.</source>
            <translation>“%1” now uses station %2.</translation>
        </message>
        <message>
            <source>&amp;Cancel Scan</source>
            <translation>&amp;Cancel Scan</translation>
        </message>
        <message>
            <source>RUN</source>
            <translation>RUN</translation>
        </message>
        <message>
            <source>STOP</source>
            <translation>STOP</translation>
        </message>
    </context>
    <context>
        <name>Fatek::SnapshotDialog</name>
        <message>
            <source>Memory Snapshot</source>
            <translation>Memory Snapshot</translation>
        </message>
        <message>
            <source>R0..R99, M0..M63 (empty: every element the PLC reports)</source>
            <translation>R0..R99, M0..M63 (empty: every element the PLC reports)</translation>
        </message>
        <message>
            <source>Ranges:</source>
            <translation>Ranges:</translation>
        </message>
        <message>
            <source>Take Snapshot</source>
            <translation>Take Snapshot</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancel</translation>
        </message>
        <message>
            <source>Save…</source>
            <translation>Save…</translation>
        </message>
        <message>
            <source>Open…</source>
            <translation>Open…</translation>
        </message>
        <message>
            <source>Compare With PLC</source>
            <translation>Compare With PLC</translation>
        </message>
        <message>
            <source>Compare With File…</source>
            <translation>Compare With File…</translation>
        </message>
        <message>
            <source>Export Differences…</source>
            <translation>Export Differences…</translation>
        </message>
        <message>
            <source>Filter</source>
            <translation>Filter</translation>
        </message>
        <message>
            <source>Ranges to restore (empty: all but the inputs X)</source>
            <translation>Ranges to restore (empty: all but the inputs X)</translation>
        </message>
        <message>
            <source>Restore Values…</source>
            <translation>Restore Values…</translation>
        </message>
        <message>
            <source>Save Snapshot</source>
            <translation>Save Snapshot</translation>
        </message>
        <message>
            <source>Open Snapshot</source>
            <translation>Open Snapshot</translation>
        </message>
        <message>
            <source>Compare With File</source>
            <translation>Compare With File</translation>
        </message>
        <message>
            <source>Export Differences</source>
            <translation>Export Differences</translation>
        </message>
        <message>
            <source>Snapshots (*.json *.csv)</source>
            <translation>Snapshots (*.json *.csv)</translation>
        </message>
        <message>
            <source>Stopped: the target changed.</source>
            <translation>Stopped: the target changed.</translation>
        </message>
        <message>
            <source>Snapshot: %1 values, %2, station %3, %4</source>
            <translation>Snapshot: %1 values, %2, station %3, %4</translation>
        </message>
        <message>
            <source>No snapshot yet: take one or open a file.</source>
            <translation>No snapshot yet: take one or open a file.</translation>
        </message>
        <message>
            <source>Reading…</source>
            <translation>Reading…</translation>
        </message>
        <message>
            <source>Snapshot</source>
            <translation>Snapshot</translation>
        </message>
        <message>
            <source>PLC</source>
            <translation>PLC</translation>
        </message>
        <message>
            <source>Saved %1.</source>
            <translation>Saved %1.</translation>
        </message>
        <message>
            <source>Before</source>
            <translation>Before</translation>
        </message>
        <message>
            <source>After</source>
            <translation>After</translation>
        </message>
        <message>
            <source>Opened %1.</source>
            <translation>Opened %1.</translation>
        </message>
        <message>
            <source>File</source>
            <translation>File</translation>
        </message>
        <message>
            <source>Exported %1 differences to %2.</source>
            <translation>Exported %1 differences to %2.</translation>
        </message>
        <message numerus="yes">
            <source>Write %1 values of the snapshot to %2 in %n request(s), then read them back?</source>
            <translation>
                <numerusform>Write %1 values of the snapshot to %2 in %n request, then read them back?</numerusform>
                <numerusform>Write %1 values of the snapshot to %2 in %n requests, then read them back?</numerusform>
            </translation>
        </message>
        <message>
            <source>The snapshot is of another model than the PLC at %1.

Snapshot: %2
PLC: %3

Write its values all the same? Elements the PLC does not have are refused before anything is written.</source>
            <translation>The snapshot is of another model than the PLC at %1.

Snapshot: %2
PLC: %3

Write its values all the same? Elements the PLC does not have are refused before anything is written.</translation>
        </message>
        <message>
            <source>Restore Values</source>
            <translation>Restore Values</translation>
        </message>
        <message>
            <source>Not restored: nothing was written.</source>
            <translation>Not restored: nothing was written.</translation>
        </message>
        <message>
            <source>Writing…</source>
            <translation>Writing…</translation>
        </message>
        <message>
            <source>Written</source>
            <translation>Written</translation>
        </message>
        <message>
            <source>Read back</source>
            <translation>Read back</translation>
        </message>
        <message numerus="yes">
            <source>The memory snapshot of %n value(s) taken at %1 from station %2 is not saved.</source>
            <translation>
                <numerusform>The memory snapshot of %n value taken at %1 from station %2 is not saved.</numerusform>
                <numerusform>The memory snapshot of %n values taken at %1 from station %2 is not saved.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>Fatek::CheckoutTableModel</name>
        <message>
            <source>forced: seen?</source>
            <translation>forced: seen?</translation>
        </message>
        <message>
            <source>now %1</source>
            <translation>now %1</translation>
        </message>
        <message>
            <source>%1; now %2</source>
            <translation>%1; now %2</translation>
        </message>
        <message>
            <source>Group</source>
            <translation>Group</translation>
        </message>
        <message>
            <source>Point</source>
            <translation>Point</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>Name</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>Kind</translation>
        </message>
        <message>
            <source>State</source>
            <translation>State</translation>
        </message>
        <message>
            <source>Times / values</source>
            <translation>Times / values</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>Comment</translation>
        </message>
        <message>
            <source>%1 %: %2 expected</source>
            <translation>%1 %: %2 expected</translation>
        </message>
        <message>
            <source>Attempt %1: %2, %3 by %4</source>
            <translation>Attempt %1: %2, %3 by %4</translation>
        </message>
        <message>
            <source>(no name)</source>
            <translation>(no name)</translation>
        </message>
        <message>
            <source>%1 (attempt %2)</source>
            <translation>%1 (attempt %2)</translation>
        </message>
        <message>
            <source>no scale: import a plan CSV with it</source>
            <translation>no scale: import a plan CSV with it</translation>
        </message>
        <message>
            <source>%1; next %2</source>
            <translation>%1; next %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::CheckoutKeys</name>
        <message>
            <source>Space: passed (an output is forced first), F: failed, R: passed with remark, D: deferred, A: not applicable, T: test again, N: next point, V: read the next analog check, Shift+V: read it again as left, F2: comment</source>
            <translation>Space: passed (an output is forced first), F: failed, R: passed with remark, D: deferred, A: not applicable, T: test again, N: next point, V: read the next analog check, Shift+V: read it again as left, F2: comment</translation>
        </message>
        <message>
            <source>%1 (%2)</source>
            <translation>%1 (%2)</translation>
        </message>
        <message>
            <source>Answer for %1 first (Space: seen, F: not seen).</source>
            <translation>Answer for %1 first (Space: seen, F: not seen).</translation>
        </message>
        <message>
            <source>Deferred</source>
            <translation>Deferred</translation>
        </message>
        <message>
            <source>Passed with Remark</source>
            <translation>Passed with Remark</translation>
        </message>
        <message>
            <source>Why is %1 deferred (what is missing, until when)?</source>
            <translation>Why is %1 deferred (what is missing, until when)?</translation>
        </message>
        <message>
            <source>The remark on %1 (what was not as it should be):</source>
            <translation>The remark on %1 (what was not as it should be):</translation>
        </message>
        <message>
            <source>Nothing recorded on %1.</source>
            <translation>Nothing recorded on %1.</translation>
        </message>
        <message>
            <source>%1 is tested again: actuate it in the field.</source>
            <translation>%1 is tested again: actuate it in the field.</translation>
        </message>
        <message>
            <source>%1 is tested again: Space forces it.</source>
            <translation>%1 is tested again: Space forces it.</translation>
        </message>
        <message>
            <source>%1 is tested again: V reads its checks.</source>
            <translation>%1 is tested again: V reads its checks.</translation>
        </message>
        <message>
            <source>%1. Import a plan CSV that gives its scale (Import… &gt; Plan CSV…).</source>
            <translation>%1. Import a plan CSV that gives its scale (Import… &gt; Plan CSV…).</translation>
        </message>
        <message>
            <source>Reading %1…</source>
            <translation>Reading %1…</translation>
        </message>
        <message>
            <source>%1: %2.</source>
            <translation>%1: %2.</translation>
        </message>
        <message>
            <source>%1 read. Next: %2 (V); Shift+V reads the last check again as left.</source>
            <translation>%1 read. Next: %2 (V); Shift+V reads the last check again as left.</translation>
        </message>
        <message>
            <source>Start the checkout first: outputs are forced only while it runs.</source>
            <translation>Start the checkout first: outputs are forced only while it runs.</translation>
        </message>
        <message>
            <source>Operator mode: outputs are not forced.</source>
            <translation>Operator mode: outputs are not forced.</translation>
        </message>
        <message>
            <source>Force %1 on at %2? It stays on until you answer, then it is released.</source>
            <translation>Force %1 on at %2? It stays on until you answer, then it is released.</translation>
        </message>
        <message>
            <source>Force Output</source>
            <translation>Force Output</translation>
        </message>
        <message>
            <source>Not forced: nothing was written.</source>
            <translation>Not forced: nothing was written.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::CheckoutDetailsDialog</name>
        <message>
            <source>Checkout Details</source>
            <translation>Checkout Details</translation>
        </message>
        <message>
            <source>Document ID:</source>
            <translation>Document ID:</translation>
        </message>
        <message>
            <source>Revision:</source>
            <translation>Revision:</translation>
        </message>
        <message>
            <source>Engineer&apos;s company:</source>
            <translation>Engineer&apos;s company:</translation>
        </message>
        <message>
            <source>Witness:</source>
            <translation>Witness:</translation>
        </message>
        <message>
            <source>Witness&apos;s company:</source>
            <translation>Witness&apos;s company:</translation>
        </message>
        <message>
            <source>Signs for the customer:</source>
            <translation>Signs for the customer:</translation>
        </message>
    </context>
    <context>
        <name>Fatek::CsvFileFilter</name>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>CSV files (*.csv)</translation>
        </message>
        <message>
            <source>CSV, Windows line ends (*.csv)</source>
            <translation>CSV, Windows line ends (*.csv)</translation>
        </message>
    </context>
    <context>
        <name>Fatek::CheckoutPunchDialog</name>
        <message>
            <source>Punch List</source>
            <translation>Punch List</translation>
        </message>
        <message>
            <source>Close Out</source>
            <translation>Close Out</translation>
        </message>
        <message>
            <source>Close out the chosen item: its point passes now</source>
            <translation>Close out the chosen item: its point passes now</translation>
        </message>
        <message>
            <source>Export CSV…</source>
            <translation>Export CSV…</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>Close</translation>
        </message>
        <message>
            <source>Choose the item to close out.</source>
            <translation>Choose the item to close out.</translation>
        </message>
        <message>
            <source>Export Punch List</source>
            <translation>Export Punch List</translation>
        </message>
        <message>
            <source>%1 is closed out.</source>
            <translation>%1 is closed out.</translation>
        </message>
        <message>
            <source>Punch list written: %1</source>
            <translation>Punch list written: %1</translation>
        </message>
    </context>
    <context>
        <name>Fatek::IoCheckoutDialog</name>
        <message>
            <source>I/O Checkout</source>
            <translation>I/O Checkout</translation>
        </message>
        <message>
            <source>X0..X15, Y0..Y7, R100</source>
            <translation>X0..X15, Y0..Y7, R100</translation>
        </message>
        <message>
            <source>Points:</source>
            <translation>Points:</translation>
        </message>
        <message>
            <source>Project:</source>
            <translation>Project:</translation>
        </message>
        <message>
            <source>Customer:</source>
            <translation>Customer:</translation>
        </message>
        <message>
            <source>Engineer:</source>
            <translation>Engineer:</translation>
        </message>
        <message>
            <source>New</source>
            <translation>New</translation>
        </message>
        <message>
            <source>Open…</source>
            <translation>Open…</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>Start</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>Stop</translation>
        </message>
        <message>
            <source>Report…</source>
            <translation>Report…</translation>
        </message>
        <message>
            <source>Write the report as PDF or CSV</source>
            <translation>Write the report as PDF or CSV</translation>
        </message>
        <message>
            <source>Open Checkout</source>
            <translation>Open Checkout</translation>
        </message>
        <message>
            <source>Checkouts (*.json)</source>
            <translation>Checkouts (*.json)</translation>
        </message>
        <message>
            <source>Checkout Report</source>
            <translation>Checkout Report</translation>
        </message>
        <message>
            <source>Watching the inputs: actuate %1 in the field.</source>
            <translation>Watching the inputs: actuate %1 in the field.</translation>
        </message>
        <message>
            <source>%1 is forced on. Seen in the field? Space: seen, F: not seen.</source>
            <translation>%1 is forced on. Seen in the field? Space: seen, F: not seen.</translation>
        </message>
        <message>
            <source>%1 is released.</source>
            <translation>%1 is released.</translation>
        </message>
        <message>
            <source>Force Output</source>
            <translation>Force Output</translation>
        </message>
        <message>
            <source>Stopped: the target changed.</source>
            <translation>Stopped: the target changed.</translation>
        </message>
        <message>
            <source>(operator mode: outputs are not forced)</source>
            <translation>(operator mode: outputs are not forced)</translation>
        </message>
        <message>
            <source>Save Checkout</source>
            <translation>Save Checkout</translation>
        </message>
        <message>
            <source>Reading the PLC&apos;s status…</source>
            <translation>Reading the PLC&apos;s status…</translation>
        </message>
        <message>
            <source>Opened %1.</source>
            <translation>Opened %1.</translation>
        </message>
        <message>
            <source>The checkout left %1 forced on %2. Release them now?</source>
            <translation>The checkout left %1 forced on %2. Release them now?</translation>
        </message>
        <message>
            <source>Release Outputs</source>
            <translation>Release Outputs</translation>
        </message>
        <message>
            <source>Still forced: %1 (Start releases them).</source>
            <translation>Still forced: %1 (Start releases them).</translation>
        </message>
        <message>
            <source>Report written: %1</source>
            <translation>Report written: %1</translation>
        </message>
        <message>
            <source>The latest results of the checkout are not saved: %1</source>
            <translation>The latest results of the checkout are not saved: %1</translation>
        </message>
        <message>
            <source>Import…</source>
            <translation>Import…</translation>
        </message>
        <message>
            <source>A plan from a CSV file, or from the names imported in the main window</source>
            <translation>A plan from a CSV file, or from the names imported in the main window</translation>
        </message>
        <message>
            <source>Details…</source>
            <translation>Details…</translation>
        </message>
        <message>
            <source>Document ID, revision and who signs the report</source>
            <translation>Document ID, revision and who signs the report</translation>
        </message>
        <message>
            <source>Punch List…</source>
            <translation>Punch List…</translation>
        </message>
        <message>
            <source>The failed and deferred points: owner, close-out, CSV</source>
            <translation>The failed and deferred points: owner, close-out, CSV</translation>
        </message>
        <message>
            <source>Releasing %1… the window closes once the PLC confirms it.</source>
            <translation>Releasing %1… the window closes once the PLC confirms it.</translation>
        </message>
        <message>
            <source>Close I/O Checkout</source>
            <translation>Close I/O Checkout</translation>
        </message>
        <message>
            <source>%1 is not confirmed released on %2. Close anyway? The checkout file keeps it listed: the next Open releases it.</source>
            <translation>%1 is not confirmed released on %2. Close anyway? The checkout file keeps it listed: the next Open releases it.</translation>
        </message>
        <message>
            <source>Plan CSV…</source>
            <translation>Plan CSV…</translation>
        </message>
        <message>
            <source>Import Checkout Plan</source>
            <translation>Import Checkout Plan</translation>
        </message>
        <message>
            <source>Checkout plans (*.csv)</source>
            <translation>Checkout plans (*.csv)</translation>
        </message>
        <message>
            <source>Imported Names…</source>
            <translation>Imported Names…</translation>
        </message>
        <message>
            <source>The names that start with (empty: every name):</source>
            <translation>The names that start with (empty: every name):</translation>
        </message>
        <message>
            <source>PDF…</source>
            <translation>PDF…</translation>
        </message>
        <message>
            <source>CSV…</source>
            <translation>CSV…</translation>
        </message>
        <message>
            <source>CSV with Windows Line Ends…</source>
            <translation>CSV with Windows Line Ends…</translation>
        </message>
        <message>
            <source>PDF reports (*.pdf)</source>
            <translation>PDF reports (*.pdf)</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>CSV files (*.csv)</translation>
        </message>
        <message numerus="yes">
            <source>Imported %1: %n point(s).</source>
            <translation>
                <numerusform>Imported %1: %n point.</numerusform>
                <numerusform>Imported %1: %n points.</numerusform>
            </translation>
        </message>
        <message>
            <source>No names are imported: File &gt; Import Names and Comments… in the main window first.</source>
            <translation>No names are imported: File &gt; Import Names and Comments… in the main window first.</translation>
        </message>
        <message numerus="yes">
            <source>A plan of %n point(s) from the imported names.</source>
            <translation>
                <numerusform>A plan of %n point from the imported names.</numerusform>
                <numerusform>A plan of %n points from the imported names.</numerusform>
            </translation>
        </message>
        <message>
            <source>The report&apos;s details are set.</source>
            <translation>The report&apos;s details are set.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ToolDialogFrame</name>
        <message>
            <source>Station %1 on “%2”</source>
            <translation>Station %1 on “%2”</translation>
        </message>
        <message>
            <source>No connection: choose a connection and a station.</source>
            <translation>No connection: choose a connection and a station.</translation>
        </message>
        <message>
            <source>Save it first? Discarded, it is lost.</source>
            <translation>Save it first? Discarded, it is lost.</translation>
        </message>
        <message>
            <source>&amp;Save…</source>
            <translation>&amp;Save…</translation>
        </message>
        <message>
            <source>&amp;Discard</source>
            <translation>&amp;Discard</translation>
        </message>
    </context>
    <context>
        <name>Fatek::SnapshotDiffModel</name>
        <message>
            <source>Before</source>
            <translation>Before</translation>
        </message>
        <message>
            <source>After</source>
            <translation>After</translation>
        </message>
        <message>
            <source>Address</source>
            <translation>Address</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmAnnunciator</name>
        <message>
            <source>&amp;Mute Alarm Sound</source>
            <translation>&amp;Mute Alarm Sound</translation>
        </message>
        <message>
            <source>Open the alarm summary</source>
            <translation>Open the alarm summary</translation>
        </message>
        <message>
            <source>No sound while alarms wait for an acknowledge</source>
            <translation>No sound while alarms wait for an acknowledge</translation>
        </message>
        <message numerus="yes">
            <source>%n unacknowledged alarm(s)</source>
            <translation>
                <numerusform>%n unacknowledged alarm</numerusform>
                <numerusform>%n unacknowledged alarms</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmCenter</name>
        <message>
            <source>Alarm journal %1: %2</source>
            <translation>Alarm journal %1: %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmDefinitionDialog</name>
        <message>
            <source> s</source>
            <translation> s</translation>
        </message>
        <message>
            <source>Alarms of %1</source>
            <translation>Alarms of %1</translation>
        </message>
        <message>
            <source>Alarms of %1 (%2)</source>
            <translation>Alarms of %1 (%2)</translation>
        </message>
        <message>
            <source>Alarm</source>
            <translation>Alarm</translation>
        </message>
        <message>
            <source>Limit</source>
            <translation>Limit</translation>
        </message>
        <message>
            <source>Deadband</source>
            <translation>Deadband</translation>
        </message>
        <message>
            <source>On delay</source>
            <translation>On delay</translation>
        </message>
        <message>
            <source>Off delay</source>
            <translation>Off delay</translation>
        </message>
        <message>
            <source>Priority</source>
            <translation>Priority</translation>
        </message>
        <message>
            <source>Message</source>
            <translation>Message</translation>
        </message>
        <message>
            <source>Group</source>
            <translation>Group</translation>
        </message>
        <message>
            <source>In service</source>
            <translation>In service</translation>
        </message>
        <message>
            <source>Limits are in the item&apos;s format (%1). A high alarm clears when the value is below its limit by the deadband; the delays say how long a condition must hold before it raises or clears the alarm.</source>
            <translation>Limits are in the item&apos;s format (%1). A high alarm clears when the value is below its limit by the deadband; the delays say how long a condition must hold before it raises or clears the alarm.</translation>
        </message>
        <message>
            <source>The delays say how long a condition must hold before it raises or clears the alarm. A bad quality alarm is raised when the item is stale or in error for its on delay.</source>
            <translation>The delays say how long a condition must hold before it raises or clears the alarm. A bad quality alarm is raised when the item is stale or in error for its on delay.</translation>
        </message>
        <message>
            <source>Off: out of service, never raised (kept in the list)</source>
            <translation>Off: out of service, never raised (kept in the list)</translation>
        </message>
        <message>
            <source>%1: type the limit.</source>
            <translation>%1: type the limit.</translation>
        </message>
        <message>
            <source>%1: the limit &quot;%2&quot; is not a number.</source>
            <translation>%1: the limit &quot;%2&quot; is not a number.</translation>
        </message>
        <message>
            <source>%1: the deadband &quot;%2&quot; is not a number.</source>
            <translation>%1: the deadband &quot;%2&quot; is not a number.</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmEventsModel</name>
        <message>
            <source>%1 until %2</source>
            <translation>%1 until %2</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>Time</translation>
        </message>
        <message>
            <source>Connection</source>
            <translation>Connection</translation>
        </message>
        <message>
            <source>Alarm</source>
            <translation>Alarm</translation>
        </message>
        <message>
            <source>Event</source>
            <translation>Event</translation>
        </message>
        <message>
            <source>State after</source>
            <translation>State after</translation>
        </message>
        <message>
            <source>Priority</source>
            <translation>Priority</translation>
        </message>
        <message>
            <source>Message</source>
            <translation>Message</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Value</translation>
        </message>
        <message>
            <source>User</source>
            <translation>User</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>Comment</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmJournalDialog</name>
        <message>
            <source>&amp;Show</source>
            <translation>&amp;Show</translation>
        </message>
        <message>
            <source>&amp;Export CSV…</source>
            <translation>&amp;Export CSV…</translation>
        </message>
        <message>
            <source>Alarm Journal</source>
            <translation>Alarm Journal</translation>
        </message>
        <message>
            <source>All connections</source>
            <translation>All connections</translation>
        </message>
        <message>
            <source>From:</source>
            <translation>From:</translation>
        </message>
        <message>
            <source>To:</source>
            <translation>To:</translation>
        </message>
        <message>
            <source>Connection:</source>
            <translation>Connection:</translation>
        </message>
        <message>
            <source>The end of the range must come after its start.</source>
            <translation>The end of the range must come after its start.</translation>
        </message>
        <message>
            <source>Reading the journal…</source>
            <translation>Reading the journal…</translation>
        </message>
        <message>
            <source>The journal could not be read: %1</source>
            <translation>The journal could not be read: %1</translation>
        </message>
        <message numerus="yes">
            <source>%n event(s).</source>
            <translation>
                <numerusform>%n event.</numerusform>
                <numerusform>%n events.</numerusform>
            </translation>
        </message>
        <message>
            <source>Export Alarm Journal</source>
            <translation>Export Alarm Journal</translation>
        </message>
        <message>
            <source>All files (*)</source>
            <translation>All files (*)</translation>
        </message>
        <message>
            <source>Not exported: %1</source>
            <translation>Not exported: %1</translation>
        </message>
        <message numerus="yes">
            <source>%n event(s) written to %1.</source>
            <translation>
                <numerusform>%n event written to %1.</numerusform>
                <numerusform>%n events written to %1.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmsUi</name>
        <message>
            <source>Alarms</source>
            <translation>Alarms</translation>
        </message>
        <message>
            <source>&amp;Alarm Summary</source>
            <translation>&amp;Alarm Summary</translation>
        </message>
        <message>
            <source>Alarm &amp;Journal…</source>
            <translation>Alarm &amp;Journal…</translation>
        </message>
        <message>
            <source>&amp;Alarms…</source>
            <translation>&amp;Alarms…</translation>
        </message>
        <message>
            <source>Limits, bit and quality alarms of the row (not in operator mode)</source>
            <translation>Limits, bit and quality alarms of the row (not in operator mode)</translation>
        </message>
        <message>
            <source>Operator mode: alarm definitions cannot be changed.</source>
            <translation>Operator mode: alarm definitions cannot be changed.</translation>
        </message>
        <message>
            <source>Select the row whose alarms to edit.</source>
            <translation>Select the row whose alarms to edit.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmSummaryModel</name>
        <message>
            <source>shelved until %1</source>
            <translation>shelved until %1</translation>
        </message>
        <message>
            <source>%1, chattering</source>
            <translation>%1, chattering</translation>
        </message>
        <message>
            <source>State</source>
            <translation>State</translation>
        </message>
        <message>
            <source>Priority</source>
            <translation>Priority</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>Time</translation>
        </message>
        <message>
            <source>Connection</source>
            <translation>Connection</translation>
        </message>
        <message>
            <source>Item</source>
            <translation>Item</translation>
        </message>
        <message>
            <source>Message</source>
            <translation>Message</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Value</translation>
        </message>
        <message>
            <source>Group</source>
            <translation>Group</translation>
        </message>
        <message>
            <source>%1 (%2, station %3)</source>
            <translation>%1 (%2, station %3)</translation>
        </message>
        <message>
            <source>Chattering: raised %1 times or more within a minute.</source>
            <translation>Chattering: raised %1 times or more within a minute.</translation>
        </message>
        <message>
            <source>Last action by %1</source>
            <translation>Last action by %1</translation>
        </message>
        <message>
            <source>Last action by %1: %2</source>
            <translation>Last action by %1: %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmSummaryWidget</name>
        <message>
            <source>All priorities</source>
            <translation>All priorities</translation>
        </message>
        <message>
            <source>All states</source>
            <translation>All states</translation>
        </message>
        <message>
            <source>Unacknowledged</source>
            <translation>Unacknowledged</translation>
        </message>
        <message>
            <source>Active</source>
            <translation>Active</translation>
        </message>
        <message>
            <source>Shelved</source>
            <translation>Shelved</translation>
        </message>
        <message>
            <source>Out of service</source>
            <translation>Out of service</translation>
        </message>
        <message>
            <source>All groups</source>
            <translation>All groups</translation>
        </message>
        <message>
            <source>Filter: item, message, group or connection</source>
            <translation>Filter: item, message, group or connection</translation>
        </message>
        <message>
            <source>Comment (optional)</source>
            <translation>Comment (optional)</translation>
        </message>
        <message>
            <source>Kept in the journal with the next acknowledge or shelve</source>
            <translation>Kept in the journal with the next acknowledge or shelve</translation>
        </message>
        <message>
            <source>&amp;Acknowledge</source>
            <translation>&amp;Acknowledge</translation>
        </message>
        <message>
            <source>Acknowledge All &amp;Shown</source>
            <translation>Acknowledge All &amp;Shown</translation>
        </message>
        <message>
            <source>Acknowledge (Ctrl+K)</source>
            <translation>Acknowledge (Ctrl+K)</translation>
        </message>
        <message>
            <source>Acknowledge the selected alarms</source>
            <translation>Acknowledge the selected alarms</translation>
        </message>
        <message>
            <source>Acknowledge All Shown</source>
            <translation>Acknowledge All Shown</translation>
        </message>
        <message>
            <source>Acknowledge every alarm the filters show (Ctrl+Shift+K)</source>
            <translation>Acknowledge every alarm the filters show (Ctrl+Shift+K)</translation>
        </message>
        <message>
            <source>Shelve</source>
            <translation>Shelve</translation>
        </message>
        <message>
            <source>Hide the selected alarms for a while; they come back by themselves</source>
            <translation>Hide the selected alarms for a while; they come back by themselves</translation>
        </message>
        <message>
            <source>For 15 min</source>
            <translation>For 15 min</translation>
        </message>
        <message>
            <source>For 1 h</source>
            <translation>For 1 h</translation>
        </message>
        <message>
            <source>For 8 h</source>
            <translation>For 8 h</translation>
        </message>
        <message>
            <source>For a Time…</source>
            <translation>For a Time…</translation>
        </message>
        <message>
            <source>Unshelve</source>
            <translation>Unshelve</translation>
        </message>
        <message>
            <source>Journal…</source>
            <translation>Journal…</translation>
        </message>
        <message>
            <source>Every raise, acknowledge, return and shelve, by time; export to CSV</source>
            <translation>Every raise, acknowledge, return and shelve, by time; export to CSV</translation>
        </message>
        <message>
            <source>Select the alarms first (click a row, or the arrow keys).</source>
            <translation>Select the alarms first (click a row, or the arrow keys).</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>Acknowledged: %1.</source>
            <translation>Acknowledged: %1.</translation>
        </message>
        <message>
            <source>No alarm shown waits for an acknowledge.</source>
            <translation>No alarm shown waits for an acknowledge.</translation>
        </message>
        <message>
            <source>Shelved until %1: %2.</source>
            <translation>Shelved until %1: %2.</translation>
        </message>
        <message>
            <source>Shelve Alarms</source>
            <translation>Shelve Alarms</translation>
        </message>
        <message>
            <source>Shelve the selected alarms for (minutes):</source>
            <translation>Shelve the selected alarms for (minutes):</translation>
        </message>
        <message>
            <source>Unshelved: %1.</source>
            <translation>Unshelved: %1.</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmText</name>
        <message>
            <source>normal</source>
            <translation>normal</translation>
        </message>
        <message>
            <source>active, unacknowledged</source>
            <translation>active, unacknowledged</translation>
        </message>
        <message>
            <source>active, acknowledged</source>
            <translation>active, acknowledged</translation>
        </message>
        <message>
            <source>returned, unacknowledged</source>
            <translation>returned, unacknowledged</translation>
        </message>
        <message>
            <source>shelved</source>
            <translation>shelved</translation>
        </message>
        <message>
            <source>out of service</source>
            <translation>out of service</translation>
        </message>
        <message>
            <source>critical</source>
            <translation>critical</translation>
        </message>
        <message>
            <source>high</source>
            <translation>high</translation>
        </message>
        <message>
            <source>medium</source>
            <translation>medium</translation>
        </message>
        <message>
            <source>low</source>
            <translation>low</translation>
        </message>
        <message>
            <source>High-high</source>
            <translation>High-high</translation>
        </message>
        <message>
            <source>High</source>
            <translation>High</translation>
        </message>
        <message>
            <source>Low</source>
            <translation>Low</translation>
        </message>
        <message>
            <source>Low-low</source>
            <translation>Low-low</translation>
        </message>
        <message>
            <source>Bit on (1)</source>
            <translation>Bit on (1)</translation>
        </message>
        <message>
            <source>Bit off (0)</source>
            <translation>Bit off (0)</translation>
        </message>
        <message>
            <source>Bad quality</source>
            <translation>Bad quality</translation>
        </message>
        <message>
            <source>raised</source>
            <translation>raised</translation>
        </message>
        <message>
            <source>returned</source>
            <translation>returned</translation>
        </message>
        <message>
            <source>acknowledged</source>
            <translation>acknowledged</translation>
        </message>
        <message>
            <source>unshelved</source>
            <translation>unshelved</translation>
        </message>
        <message>
            <source>in service</source>
            <translation>in service</translation>
        </message>
        <message>
            <source>%1 min</source>
            <translation>%1 min</translation>
        </message>
        <message>
            <source>%1 h</source>
            <translation>%1 h</translation>
        </message>
        <message>
            <source>%1 h %2 min</source>
            <translation>%1 h %2 min</translation>
        </message>
    </context>
</TS>
