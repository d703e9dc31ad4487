<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_TW">
    <context>
        <name>Fatek::ConnectionDialog</name>
        <message>
            <source>New Connection</source>
            <translation>新增連線</translation>
        </message>
        <message>
            <source>(new)</source>
            <translation>（新增）</translation>
        </message>
        <message>
            <source>%1 — %2</source>
            <translation>%1 — %2</translation>
        </message>
        <message>
            <source>e.g. Pump station</source>
            <translation>例如：泵浦站</translation>
        </message>
        <message>
            <source>Serial (RS-232 / RS-485)</source>
            <translation>串列埠 (RS-232 / RS-485)</translation>
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
            <translation>重新整理</translation>
        </message>
        <message>
            <source>&amp;Port:</source>
            <translation>連接埠(&amp;P)：</translation>
        </message>
        <message>
            <source>&amp;Baud rate:</source>
            <translation>鮑率(&amp;B)：</translation>
        </message>
        <message>
            <source>&amp;Data bits:</source>
            <translation>資料位元(&amp;D)：</translation>
        </message>
        <message>
            <source>None</source>
            <translation>無</translation>
        </message>
        <message>
            <source>Even</source>
            <translation>偶同位</translation>
        </message>
        <message>
            <source>Odd</source>
            <translation>奇同位</translation>
        </message>
        <message>
            <source>Pa&amp;rity:</source>
            <translation>同位檢查(&amp;R)：</translation>
        </message>
        <message>
            <source>&amp;Stop bits:</source>
            <translation>停止位元(&amp;S)：</translation>
        </message>
        <message>
            <source>Hardware (RTS/CTS)</source>
            <translation>硬體 (RTS/CTS)</translation>
        </message>
        <message>
            <source>Software (XON/XOFF)</source>
            <translation>軟體 (XON/XOFF)</translation>
        </message>
        <message>
            <source>&amp;Flow control:</source>
            <translation>流量控制(&amp;F)：</translation>
        </message>
        <message>
            <source>&amp;Host:</source>
            <translation>主機(&amp;H)：</translation>
        </message>
        <message>
            <source>Po&amp;rt:</source>
            <translation>埠號(&amp;R)：</translation>
        </message>
        <message>
            <source>FACON (ASCII)</source>
            <translation>FACON (ASCII)</translation>
        </message>
        <message>
            <source>Binary</source>
            <translation>二進位</translation>
        </message>
        <message>
            <source>Auto-detect</source>
            <translation>自動偵測</translation>
        </message>
        <message>
            <source> ms</source>
            <translation> ms</translation>
        </message>
        <message>
            <source>Re&amp;cent:</source>
            <translation>最近使用(&amp;C)：</translation>
        </message>
        <message>
            <source>&amp;Name:</source>
            <translation>名稱(&amp;N)：</translation>
        </message>
        <message>
            <source>&amp;Link:</source>
            <translation>連線方式(&amp;L)：</translation>
        </message>
        <message>
            <source>&amp;URL:</source>
            <translation>網址(&amp;U)：</translation>
        </message>
        <message>
            <source>The link as fatek-cli --link takes it (tcp://HOST:PORT, udp://…, serial:///dev/ttyUSB0?baud=19200&amp;format=7E1): type or paste one to fill the fields; it follows them.</source>
            <translation>與命令列工具 --link 相同寫法的連線（tcp://主機:埠、udp://…、serial:///dev/ttyUSB0?baud=19200&amp;format=7E1）：輸入或貼上即填入下列欄位；欄位變更時隨之更新。</translation>
        </message>
        <message>
            <source>Pro&amp;tocol:</source>
            <translation>通訊協定(&amp;T)：</translation>
        </message>
        <message>
            <source>St&amp;ation:</source>
            <translation>站號(&amp;A)：</translation>
        </message>
        <message>
            <source>T&amp;imeout:</source>
            <translation>逾時(&amp;I)：</translation>
        </message>
        <message>
            <source>R&amp;etries:</source>
            <translation>重試次數(&amp;E)：</translation>
        </message>
        <message>
            <source>C&amp;onnect</source>
            <translation>連線(&amp;O)</translation>
        </message>
        <message>
            <source>PLC</source>
            <translation>PLC</translation>
        </message>
        <message>
            <source>Give the connection a name.</source>
            <translation>請為此連線命名。</translation>
        </message>
        <message>
            <source>The baud rate must be a positive number.</source>
            <translation>鮑率必須是正數。</translation>
        </message>
        <message>
            <source>MQTT gateway</source>
            <translation>MQTT 閘道器</translation>
        </message>
        <message>
            <source>mqtt://host:port, or mqtts://host:port for TLS</source>
            <translation>mqtt://主機:埠，TLS 請用 mqtts://主機:埠</translation>
        </message>
        <message>
            <source>&amp;Broker:</source>
            <translation>代理伺服器(&amp;B)：</translation>
        </message>
        <message>
            <source>Topic &amp;prefix:</source>
            <translation>主題前綴(&amp;P)：</translation>
        </message>
        <message>
            <source>e.g. line1</source>
            <translation>例如：閘道器設定中的連線名稱</translation>
        </message>
        <message>
            <source>The connection&apos;s name in the gateway&apos;s configuration</source>
            <translation>閘道器設定中的連線名稱</translation>
        </message>
        <message>
            <source>&amp;Gateway connection:</source>
            <translation>閘道器連線(&amp;G)：</translation>
        </message>
        <message>
            <source>optional</source>
            <translation>選填</translation>
        </message>
        <message>
            <source>&amp;User:</source>
            <translation>使用者(&amp;U)：</translation>
        </message>
        <message>
            <source>optional; not saved</source>
            <translation>選填；不會儲存</translation>
        </message>
        <message>
            <source>Pass&amp;word:</source>
            <translation>密碼(&amp;W)：</translation>
        </message>
        <message>
            <source>optional; mqtts:// only</source>
            <translation>選填；僅限 mqtts://</translation>
        </message>
        <message>
            <source>Browse…</source>
            <translation>瀏覽…</translation>
        </message>
        <message>
            <source>TLS CA &amp;file:</source>
            <translation>TLS CA 檔案(&amp;F)：</translation>
        </message>
        <message>
            <source>CA Certificate</source>
            <translation>CA 憑證</translation>
        </message>
        <message>
            <source>Certificates (*.crt *.pem);;All files (*)</source>
            <translation>憑證 (*.crt *.pem);;所有檔案 (*)</translation>
        </message>
        <message>
            <source>Client c&amp;ertificate:</source>
            <translation>用戶端憑證(&amp;E)：</translation>
        </message>
        <message>
            <source>Client Certificate</source>
            <translation>用戶端憑證</translation>
        </message>
        <message>
            <source>Client &amp;key:</source>
            <translation>用戶端金鑰(&amp;K)：</translation>
        </message>
        <message>
            <source>with the client certificate</source>
            <translation>搭配用戶端憑證</translation>
        </message>
        <message>
            <source>Client Key</source>
            <translation>用戶端金鑰</translation>
        </message>
        <message>
            <source>Keys (*.key *.pem);;All files (*)</source>
            <translation>金鑰 (*.key *.pem);;所有檔案 (*)</translation>
        </message>
        <message>
            <source>TLS files need an mqtts:// broker URL.</source>
            <translation>TLS 檔案需搭配 mqtts:// 代理伺服器網址。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ConnectionListModel</name>
        <message>
            <source>Round trip: last %1 ms, median %2 ms, 99% %3 ms</source>
            <translation>往返時間：最近 %1 ms，中位數 %2 ms，99% %3 ms</translation>
        </message>
        <message>
            <source>Station the tools act on; double-click to change</source>
            <translation>工具作用的站號；按兩下可變更</translation>
        </message>
        <message>
            <source>Station %1: %2 requests, %3 errors, RTT %4 ms</source>
            <translation>站號 %1：%2 次請求，%3 次錯誤，RTT %4 ms</translation>
        </message>
        <message>
            <source>URL: %1</source>
            <translation>網址：%1</translation>
        </message>
        <message>
            <source>; not answering, polled again at %1</source>
            <translation>；沒有回應，將於 %1 再次輪詢</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>名稱</translation>
        </message>
        <message>
            <source>Link</source>
            <translation>連線</translation>
        </message>
        <message>
            <source>Station</source>
            <translation>站號</translation>
        </message>
        <message>
            <source>State</source>
            <translation>狀態</translation>
        </message>
        <message>
            <source>Req/s</source>
            <translation>請求/秒</translation>
        </message>
        <message>
            <source>Errors</source>
            <translation>錯誤</translation>
        </message>
        <message>
            <source>RTT</source>
            <translation>RTT</translation>
        </message>
        <message>
            <source>%1 timeouts, %2 checksum errors, %3 PLC errors, %4 retries, %5 link failures</source>
            <translation>%1 次逾時、%2 次檢查碼錯誤、%3 次 PLC 錯誤、%4 次重試、%5 次連線失敗</translation>
        </message>
        <message>
            <source>Station %1: %2 (RUN/STOP read every %3 s)</source>
            <translation>站號 %1：%2（每 %3 秒讀取 RUN/STOP）</translation>
        </message>
        <message>
            <source>The PLC has not said what it is yet</source>
            <translation>PLC 尚未回報其機型</translation>
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
            <translation>歷史資料：%1</translation>
        </message>
        <message>
            <source>History: %1 is written again.</source>
            <translation>歷史資料：%1 已恢復寫入。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::HistorySettingsDialog</name>
        <message numerus="yes">
            <source>History Settings (%n row(s))</source>
            <translation>
                <numerusform>歷史記錄設定（%n 列）</numerusform>
            </translation>
        </message>
        <message>
            <source>Bits and texts keep every change</source>
            <translation>位元與文字會保留每一次變化</translation>
        </message>
        <message>
            <source>A change smaller than this from the last value kept is not recorded; 0: every change</source>
            <translation>與上次保留的值相差小於此值的變化不記錄；0：每一次變化都記錄</translation>
        </message>
        <message>
            <source> s</source>
            <translation> 秒</translation>
        </message>
        <message>
            <source>A value is recorded at least this often, changed or not, so that a flat line is known to be flat</source>
            <translation>不論是否變化，至少每隔這段時間記錄一次數值，以確認平坦的線確實沒有變化</translation>
        </message>
        <message>
            <source>&amp;Deadband:</source>
            <translation>不感帶(&amp;D)：</translation>
        </message>
        <message>
            <source>&amp;Heartbeat:</source>
            <translation>心跳週期(&amp;H)：</translation>
        </message>
        <message>
            <source>Recorded: the first value, every change beyond the deadband, every change of quality, and the value once per heartbeat.</source>
            <translation>記錄內容：第一個值、每一次超過不感帶的變化、每一次品質變化，以及每個心跳週期一次的數值。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::HistoryUi</name>
        <message>
            <source>Record in &amp;History</source>
            <translation>記錄到歷史資料(&amp;H)</translation>
        </message>
        <message>
            <source>Keep the values of the selected rows in the history, to look back at them in the trend (not in operator mode)</source>
            <translation>將所選列的數值保存到歷史資料，以便在趨勢圖中回顧（操作員模式下不可用）</translation>
        </message>
        <message>
            <source>History &amp;Settings…</source>
            <translation>歷史記錄設定(&amp;S)…</translation>
        </message>
        <message>
            <source>Deadband and heartbeat of the selected rows&apos; recording</source>
            <translation>所選列記錄的不感帶與心跳週期</translation>
        </message>
        <message>
            <source>Operator mode: what is recorded in the history cannot be changed.</source>
            <translation>操作員模式：無法變更要記錄到歷史資料的項目。</translation>
        </message>
        <message>
            <source>Select the rows to record in the history.</source>
            <translation>請選取要記錄到歷史資料的列。</translation>
        </message>
        <message numerus="yes">
            <source>%n row(s) recorded in the history (%1).</source>
            <translation>
                <numerusform>已將 %n 列記錄到歷史資料（%1）。</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n row(s) no longer recorded in the history.</source>
            <translation>
                <numerusform>已有 %n 列不再記錄到歷史資料。</numerusform>
            </translation>
        </message>
        <message>
            <source>Select the rows whose recording to set.</source>
            <translation>請選取要設定記錄方式的列。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::Message</name>
        <message>
            <source>Outcome unknown: %1 It may have been carried out; reading it back as soon as the PLC answers.</source>
            <translation>結果未知：%1 PLC 可能已執行；PLC 一回應就會讀回確認。</translation>
        </message>
        <message>
            <source>Done: confirmed by reading it back.</source>
            <translation>已完成：已讀回確認。</translation>
        </message>
        <message>
            <source>Not done: read back afterwards, the PLC does not hold what was sent (not carried out, or changed since by its program).</source>
            <translation>未完成：事後讀回，PLC 的值與送出的不同（未執行，或之後已被其程式改變）。</translation>
        </message>
        <message>
            <source>Outcome still unknown: it could not be read back (%1). Check the PLC.</source>
            <translation>結果仍未知：無法讀回（%1）。請檢查 PLC。</translation>
        </message>
        <message>
            <source>other queries to the PLC kept going unanswered meanwhile, so an answer could not be told apart from a late one</source>
            <translation>其間送往 PLC 的其他查詢一直沒有回應，無法分辨回應是否為遲到的回應</translation>
        </message>
        <message>
            <source>Outcome unknown: no read can tell whether it was carried out. Check the PLC.</source>
            <translation>結果未知：沒有任何讀取能確認是否已執行。請檢查 PLC。</translation>
        </message>
        <message>
            <source>Stopped at the write of %1: %2</source>
            <translation>在寫入 %1 時停止：%2</translation>
        </message>
        <message>
            <source>Not sent: it waited past its deadline (nothing reached the PLC).</source>
            <translation>未送出：等待已超過期限（沒有任何資料送達 PLC）。</translation>
        </message>
        <message>
            <source>Outcome unknown: %1 went to the gateway and no final reply came (%2); it may have been carried out.</source>
            <translation>結果未知：%1 已送往閘道器，但沒有收到最終回覆（%2），可能已執行。</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>%1; %2</source>
            <translation>%1；%2</translation>
        </message>
        <message>
            <source>no error</source>
            <translation>無錯誤</translation>
        </message>
        <message>
            <source>illegal value</source>
            <translation>不合法的數值</translation>
        </message>
        <message>
            <source>write prohibited (ROM pack)</source>
            <translation>禁止寫入（ROM 卡匣）</translation>
        </message>
        <message>
            <source>illegal format, or command cannot execute</source>
            <translation>格式不合法，或命令無法執行</translation>
        </message>
        <message>
            <source>cannot RUN: ladder checksum error</source>
            <translation>無法執行：階梯圖檢查碼錯誤</translation>
        </message>
        <message>
            <source>cannot RUN: PLC ID differs from ladder ID</source>
            <translation>無法執行：PLC ID 與階梯圖 ID 不符</translation>
        </message>
        <message>
            <source>cannot RUN: syntax check error</source>
            <translation>無法執行：語法檢查錯誤</translation>
        </message>
        <message>
            <source>cannot RUN: function not supported</source>
            <translation>無法執行：不支援的功能</translation>
        </message>
        <message>
            <source>illegal address</source>
            <translation>不合法的位址</translation>
        </message>
        <message>
            <source>unknown error code</source>
            <translation>未知的錯誤碼</translation>
        </message>
        <message>
            <source>PLC error %1: %2</source>
            <translation>PLC 錯誤 %1：%2</translation>
        </message>
        <message>
            <source>PLC error %1: %2 %3</source>
            <translation>PLC 錯誤 %1：%2 %3</translation>
        </message>
        <message>
            <source>read brief status</source>
            <translation>讀取簡要狀態</translation>
        </message>
        <message>
            <source>RUN/STOP control</source>
            <translation>RUN/STOP 控制</translation>
        </message>
        <message>
            <source>single discrete control</source>
            <translation>單一離散點控制</translation>
        </message>
        <message>
            <source>read enable/disable flags</source>
            <translation>讀取啟用/停用旗標</translation>
        </message>
        <message>
            <source>read consecutive discretes</source>
            <translation>讀取連續離散點</translation>
        </message>
        <message>
            <source>write consecutive discretes</source>
            <translation>寫入連續離散點</translation>
        </message>
        <message>
            <source>read consecutive registers</source>
            <translation>讀取連續暫存器</translation>
        </message>
        <message>
            <source>write consecutive registers</source>
            <translation>寫入連續暫存器</translation>
        </message>
        <message>
            <source>mixed read</source>
            <translation>混合讀取</translation>
        </message>
        <message>
            <source>mixed write</source>
            <translation>混合寫入</translation>
        </message>
        <message>
            <source>loopback test</source>
            <translation>迴路測試</translation>
        </message>
        <message>
            <source>read program page</source>
            <translation>讀取程式頁</translation>
        </message>
        <message>
            <source>write program page</source>
            <translation>寫入程式頁</translation>
        </message>
        <message>
            <source>read detail status</source>
            <translation>讀取詳細狀態</translation>
        </message>
        <message>
            <source>unknown command</source>
            <translation>未知的命令</translation>
        </message>
        <message>
            <source>station %1, %2 %3</source>
            <translation>站號 %1，%2 %3</translation>
        </message>
        <message>
            <source>invalid FACON frame (%1 bytes): %2</source>
            <translation>無效的 FACON 訊框（%1 位元組）：%2</translation>
        </message>
        <message>
            <source>bad binary frame (%1 bytes): %2</source>
            <translation>錯誤的二進位訊框（%1 位元組）：%2</translation>
        </message>
        <message>
            <source>answer: OK</source>
            <translation>回應：正常</translation>
        </message>
        <message>
            <source>answer: OK, %1 data chars &quot;%2&quot;</source>
            <translation>回應：正常，%1 個資料字元「%2」</translation>
        </message>
        <message>
            <source>answer: OK, %1 data bytes: %2</source>
            <translation>回應：正常，%1 個資料位元組：%2</translation>
        </message>
        <message>
            <source>answer: no error digit</source>
            <translation>回應：缺少錯誤碼字元</translation>
        </message>
        <message>
            <source>answer: no error byte</source>
            <translation>回應：缺少錯誤碼位元組</translation>
        </message>
        <message>
            <source>answer: malformed &quot;%1&quot;</source>
            <translation>回應：格式錯誤「%1」</translation>
        </message>
        <message>
            <source>answer: echo of %1 bytes</source>
            <translation>回應：%1 位元組的回送</translation>
        </message>
        <message>
            <source>answer: error %1 (%2)</source>
            <translation>回應：錯誤 %1（%2）</translation>
        </message>
        <message>
            <source>unknown command, data &quot;%1&quot;</source>
            <translation>未知的命令，資料「%1」</translation>
        </message>
        <message>
            <source>%1 chars &quot;%2&quot;</source>
            <translation>%1 個字元「%2」</translation>
        </message>
        <message>
            <source>STOP, or answer: no error</source>
            <translation>STOP，或回應：無錯誤</translation>
        </message>
        <message>
            <source>%1 elements%2</source>
            <translation>%1 個元件%2</translation>
        </message>
        <message>
            <source>page %1</source>
            <translation>第 %1 頁</translation>
        </message>
        <message>
            <source>page %1, 64 words</source>
            <translation>第 %1 頁，64 字組</translation>
        </message>
        <message>
            <source>disable %1</source>
            <translation>停用 %1</translation>
        </message>
        <message>
            <source>enable %1</source>
            <translation>啟用 %1</translation>
        </message>
        <message>
            <source>set %1</source>
            <translation>設為 ON %1</translation>
        </message>
        <message>
            <source>reset %1</source>
            <translation>復歸 OFF %1</translation>
        </message>
        <message>
            <source>link lost</source>
            <translation>連線中斷</translation>
        </message>
        <message>
            <source>stale bytes discarded</source>
            <translation>已捨棄殘留的位元組</translation>
        </message>
        <message>
            <source>received outside an answer</source>
            <translation>在回應之外收到</translation>
        </message>
        <message>
            <source>unexpected bytes</source>
            <translation>非預期的位元組</translation>
        </message>
        <message>
            <source>no query pending</source>
            <translation>沒有等待中的查詢</translation>
        </message>
        <message>
            <source>echo of the query</source>
            <translation>查詢的回送</translation>
        </message>
        <message>
            <source>raw answer</source>
            <translation>原始回應</translation>
        </message>
        <message>
            <source>raw frame</source>
            <translation>原始訊框</translation>
        </message>
        <message>
            <source>no complete frame</source>
            <translation>沒有完整的訊框</translation>
        </message>
        <message>
            <source>more than %1 bytes: rest not read</source>
            <translation>超過 %1 位元組：其餘未讀取</translation>
        </message>
        <message>
            <source>no answer within %1 ms</source>
            <translation>%1 ms 內沒有回應</translation>
        </message>
        <message>
            <source>protocol detected: %1</source>
            <translation>偵測到通訊協定：%1</translation>
        </message>
        <message>
            <source>%1 bytes, first %2 kept</source>
            <translation>%1 位元組，保留前 %2 個</translation>
        </message>
        <message>
            <source>closing</source>
            <translation>正在關閉</translation>
        </message>
        <message>
            <source>sending %1 queued write(s) first, at most %2 ms</source>
            <translation>先送出 %1 筆排隊中的寫入，最多 %2 ms</translation>
        </message>
        <message>
            <source>closed</source>
            <translation>已關閉</translation>
        </message>
        <message>
            <source>connecting</source>
            <translation>連線中</translation>
        </message>
        <message>
            <source>connected</source>
            <translation>已連線</translation>
        </message>
        <message>
            <source>lost</source>
            <translation>已中斷</translation>
        </message>
        <message>
            <source>reconnecting</source>
            <translation>重新連線中</translation>
        </message>
        <message>
            <source>link lost: %1</source>
            <translation>連線中斷：%1</translation>
        </message>
        <message>
            <source>%1; next attempt in %2 s</source>
            <translation>%1；%2 秒後重新連線</translation>
        </message>
        <message>
            <source>the session was closed</source>
            <translation>工作階段已關閉</translation>
        </message>
        <message>
            <source>the session was closed after waiting %1 ms for queued writes</source>
            <translation>等候排隊中的寫入 %1 ms 後，工作階段已關閉</translation>
        </message>
        <message>
            <source>%1 does not take data</source>
            <translation>%1 不接受資料</translation>
        </message>
        <message>
            <source>no connection to %1 within %2 ms</source>
            <translation>%2 ms 內無法連線到 %1</translation>
        </message>
        <message>
            <source>%1 closed the connection</source>
            <translation>%1 已關閉連線</translation>
        </message>
        <message>
            <source>cannot open %1: %2</source>
            <translation>無法開啟 %1：%2</translation>
        </message>
        <message>
            <source>Protocol auto-detect: station %1 answered neither in FACON nor in binary (%2)</source>
            <translation>通訊協定自動偵測：站號 %1 對 FACON 與二進位協定皆無回應（%2）</translation>
        </message>
        <message>
            <source>Not sent: a broadcast (station 0) has no station to detect the protocol with; give --protocol for a broadcast (or choose FACON or binary in the connection)</source>
            <translation>未送出：廣播（站號 0）沒有可用來偵測通訊協定的站號；廣播請指定 --protocol（或在連線設定中選擇 FACON 或二進位）</translation>
        </message>
        <message>
            <source>No answer from station %1 within %2 ms (attempt %3 of %4).</source>
            <translation>站號 %1 在 %2 ms 內沒有回應（第 %3 次，共 %4 次）。</translation>
        </message>
        <message>
            <source>No answer within %1 ms.</source>
            <translation>%1 ms 內沒有回應。</translation>
        </message>
        <message>
            <source>Not sent: the link is not open.</source>
            <translation>未送出：連線尚未開啟。</translation>
        </message>
        <message>
            <source>Not sent: the link is down (%1).</source>
            <translation>未送出：連線中斷（%1）。</translation>
        </message>
        <message>
            <source>Not sent: %1 requests are already waiting on this link (the PLC answers slower than requests arrive).</source>
            <translation>未送出：此連線已有 %1 個請求在等待（PLC 回應的速度比請求送達慢）。</translation>
        </message>
        <message>
            <source>Read-only mode: &quot;%1&quot; was not sent. Leave operator mode to change the PLC.</source>
            <translation>唯讀模式：「%1」未送出。請離開操作員模式後再變更 PLC。</translation>
        </message>
        <message>
            <source>Cancelled before it was sent.</source>
            <translation>送出前已取消。</translation>
        </message>
        <message>
            <source>Not sent: the link is closing.</source>
            <translation>未送出：連線正在關閉。</translation>
        </message>
        <message>
            <source>Not sent: %1 did not take the frame within %2 ms (%3 of %4 bytes unsent).</source>
            <translation>未送出：%1 在 %2 ms 內未接受訊框（%4 位元組中有 %3 個未送出）。</translation>
        </message>
        <message>
            <source>The answer carries fewer values than asked.</source>
            <translation>回應的數值比要求的少。</translation>
        </message>
        <message>
            <source>Could not write to %1.</source>
            <translation>無法寫入 %1。</translation>
        </message>
        <message>
            <source>not executed</source>
            <translation>未執行</translation>
        </message>
        <message>
            <source>Station %1 does not answer (%2 requests in a row); polled again at %3.</source>
            <translation>站號 %1 沒有回應（連續 %2 個請求）；將於 %3 再次輪詢。</translation>
        </message>
        <message>
            <source>Late: no new value for %1 s (polled every %2 ms); the line is busy or slow.</source>
            <translation>延遲：已 %1 秒沒有新值（每 %2 毫秒輪詢一次）；線路忙碌或速度過慢。</translation>
        </message>
        <message>
            <source>station %1 demoted after %2 requests without an answer; next try at %3</source>
            <translation>站號 %1 連續 %2 個請求無回應，已降級；下次嘗試於 %3</translation>
        </message>
        <message>
            <source>station %1 answers again; polled as usual</source>
            <translation>站號 %1 已恢復回應；恢復正常輪詢</translation>
        </message>
        <message>
            <source>station %1: items polled every %2 ms are read every %3 ms, as fast as the line allows; late is counted from that</source>
            <translation>站號 %1：每 %2 毫秒輪詢的項目實際每 %3 毫秒讀取一次，已是線路最快速度；延遲由此起算</translation>
        </message>
        <message>
            <source>station %1: items polled every %2 ms are read on time again</source>
            <translation>站號 %1：每 %2 毫秒輪詢的項目已恢復準時讀取</translation>
        </message>
        <message>
            <source>Empty address: type an element such as R12 or X0.</source>
            <translation>位址空白：請輸入元件，例如 R12 或 X0。</translation>
        </message>
        <message>
            <source>Invalid address &quot;%1&quot;: it must start with an element type such as R, X or DWM.</source>
            <translation>無效的位址「%1」：必須以元件類型開頭，例如 R、X 或 DWM。</translation>
        </message>
        <message>
            <source>Invalid address &quot;%1&quot;: unknown element type &quot;%2&quot; (known: %3).</source>
            <translation>無效的位址「%1」：未知的元件類型「%2」（可用：%3）。</translation>
        </message>
        <message>
            <source>Invalid address &quot;%1&quot;: the element number is missing (e.g. %2).</source>
            <translation>無效的位址「%1」：缺少元件編號（例如 %2）。</translation>
        </message>
        <message>
            <source>Invalid address &quot;%1&quot;: &quot;%2&quot; is not a decimal element number.</source>
            <translation>無效的位址「%1」：「%2」不是十進位的元件編號。</translation>
        </message>
        <message>
            <source>Invalid address &quot;%1&quot;: element number too large.</source>
            <translation>無效的位址「%1」：元件編號太大。</translation>
        </message>
        <message>
            <source>Address %1 is out of range: %2 numbers go from 0 to %3.</source>
            <translation>位址 %1 超出範圍：%2 的編號範圍是 0 到 %3。</translation>
        </message>
        <message>
            <source>Address %1 is not aligned: %2 must start at a multiple of %3 (e.g. %4).</source>
            <translation>位址 %1 未對齊：%2 必須從 %3 的倍數開始（例如 %4）。</translation>
        </message>
        <message>
            <source>%1 elements from %2 run past %3, the last %4.</source>
            <translation>從 %2 起的 %1 個元件超出 %3（最後一個 %4 元件）。</translation>
        </message>
        <message>
            <source>Enter the PLC&apos;s IP address or host name.</source>
            <translation>請輸入 PLC 的 IP 位址或主機名稱。</translation>
        </message>
        <message>
            <source>Port 0 is not usable; FATEK Ethernet modules usually listen on 500.</source>
            <translation>連接埠 0 無法使用；FATEK 乙太網路模組通常使用 500。</translation>
        </message>
        <message>
            <source>Choose a serial port.</source>
            <translation>請選擇串列埠。</translation>
        </message>
        <message>
            <source>Baud rate %1 is out of range (1200 to 921600).</source>
            <translation>鮑率 %1 超出範圍（1200 到 921600）。</translation>
        </message>
        <message>
            <source>Data bits must be 7 or 8, not %1.</source>
            <translation>資料位元必須是 7 或 8，而非 %1。</translation>
        </message>
        <message>
            <source>Stop bits must be 1 or 2, not %1.</source>
            <translation>停止位元必須是 1 或 2，而非 %1。</translation>
        </message>
        <message>
            <source>Timeout %1 ms is out of range (1 to 60000 ms).</source>
            <translation>逾時 %1 ms 超出範圍（1 到 60000 ms）。</translation>
        </message>
        <message>
            <source>Retries %1 is out of range (0 to 10).</source>
            <translation>重試次數 %1 超出範圍（0 到 10）。</translation>
        </message>
        <message>
            <source>Demote after %1 unanswered requests is out of range (0 to 100; 0 never demotes).</source>
            <translation>降級前的無回應請求數 %1 超出範圍（0 到 100；0 表示永不降級）。</translation>
        </message>
        <message>
            <source>A demotion of %1 ms is out of range (1000 to 600000 ms).</source>
            <translation>降級時間 %1 毫秒超出範圍（1000 到 600000 毫秒）。</translation>
        </message>
        <message>
            <source>Inter-frame silence %1 ms is out of range (0 to 1000 ms).</source>
            <translation>訊框間隔 %1 ms 超出範圍（0 到 1000 ms）。</translation>
        </message>
        <message>
            <source>Connect timeout must be at least 1 ms.</source>
            <translation>連線逾時至少必須為 1 ms。</translation>
        </message>
        <message>
            <source>Reconnect delays must be positive, the maximum not below the minimum.</source>
            <translation>重新連線延遲必須為正數，且最大值不得小於最小值。</translation>
        </message>
        <message>
            <source>No link given: write tcp://HOST[:PORT], udp://HOST[:PORT] or serial://PORT.</source>
            <translation>未指定連線：請寫 tcp://主機[:埠]、udp://主機[:埠] 或 serial://埠。</translation>
        </message>
        <message>
            <source>Link &quot;%1&quot;: start it with tcp://, udp:// or serial:// (for example tcp://192.168.1.5:500 or serial:///dev/ttyUSB0).</source>
            <translation>連線「%1」：請以 tcp://、udp:// 或 serial:// 開頭（例如 tcp://192.168.1.5:500 或 serial:///dev/ttyUSB0）。</translation>
        </message>
        <message>
            <source>Link &quot;%1&quot;: write HOST or HOST:PORT with a port from 1 to 65535; an IPv6 address goes in brackets, as in [fe80::1]:500.</source>
            <translation>連線「%1」：請寫 主機 或 主機:埠，埠號為 1 到 65535；IPv6 位址要放在方括號內。</translation>
        </message>
        <message>
            <source>Link &quot;%1&quot;: name the serial port, as in serial:///dev/ttyUSB0 or serial://COM3.</source>
            <translation>連線「%1」：請指定序列埠，例如 serial:///dev/ttyUSB0 或 serial://COM3。</translation>
        </message>
        <message>
            <source>Link &quot;%1&quot;: no setting &quot;%2&quot; (this link takes %3).</source>
            <translation>連線「%1」：沒有設定「%2」（此連線可用：%3）。</translation>
        </message>
        <message>
            <source>Link &quot;%1&quot;: %2 takes %4, not &quot;%3&quot;.</source>
            <translation>連線「%1」：%2 應為 %4，而不是「%3」。</translation>
        </message>
        <message>
            <source>Incomplete range &quot;%1&quot;: write it as first..last, e.g. R100..R163.</source>
            <translation>範圍「%1」不完整：請寫成 起點..終點，例如 R100..R163。</translation>
        </message>
        <message>
            <source>Range &quot;%1&quot; mixes %2 and %3: both ends must be the same element type.</source>
            <translation>範圍「%1」混用了 %2 與 %3：兩端必須是相同的元件類型。</translation>
        </message>
        <message>
            <source>Range &quot;%1&quot; runs backwards: write the lower address first (%2).</source>
            <translation>範圍「%1」的方向相反：請先寫較小的位址（%2）。</translation>
        </message>
        <message>
            <source>Range &quot;%1&quot; does not end on a whole element: %2 elements are %3 apart (%4, %5, ...).</source>
            <translation>範圍「%1」的結束點不在完整的元件上：%2 元件彼此相隔 %3（%4、%5、...）。</translation>
        </message>
        <message>
            <source>Range &quot;%1&quot; has %2 elements; at most %3 fit in one range.</source>
            <translation>範圍「%1」有 %2 個元件；一個範圍最多 %3 個。</translation>
        </message>
        <message>
            <source>No range given; write for example X0-255, Y0-255.</source>
            <translation>未指定範圍；例如請輸入 X0-255, Y0-255。</translation>
        </message>
        <message>
            <source>“%1” is not a hex digit; type bytes like 01 46 03 52 00 0C.</source>
            <translation>「%1」不是十六進位數字；請以 01 46 03 52 00 0C 的形式輸入位元組。</translation>
        </message>
        <message>
            <source>Nothing to send: type the frame&apos;s bytes in hex.</source>
            <translation>沒有可送出的內容：請以十六進位輸入訊框的位元組。</translation>
        </message>
        <message>
            <source>Odd number of hex digits: each byte needs two (0C, not C).</source>
            <translation>十六進位數字個數為奇數：每個位元組需要兩位數（0C，而非 C）。</translation>
        </message>
        <message>
            <source>Only printable ASCII can be typed; write control characters as &lt;STX&gt;, &lt;ETX&gt; or &lt;0D&gt;.</source>
            <translation>只能輸入可列印的 ASCII 字元；控制字元請寫成 &lt;STX&gt;、&lt;ETX&gt; 或 &lt;0D&gt;。</translation>
        </message>
        <message>
            <source>Nothing to send: type the frame.</source>
            <translation>沒有可送出的內容：請輸入訊框。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a BCD number (digits 0-9 only)</source>
            <translation>「%1」不是 BCD 數值（只能使用數字 0-9）</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a hexadecimal number</source>
            <translation>「%1」不是十六進位數值</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a binary number (only 0 and 1)</source>
            <translation>「%1」不是二進位數值（只能使用 0 與 1）</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a number</source>
            <translation>「%1」不是數值</translation>
        </message>
        <message>
            <source>BCD values cannot be negative (&quot;%1&quot;)</source>
            <translation>BCD 數值不能為負數（「%1」）</translation>
        </message>
        <message>
            <source>%1 does not fit %2 as BCD (0..%3)</source>
            <translation>%1 超出%2的 BCD 範圍（0..%3）</translation>
        </message>
        <message>
            <source>%1 does not fit %2 (%3)</source>
            <translation>%1 超出%2的範圍（%3）</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a bit value: type ON, OFF, 1 or 0</source>
            <translation>「%1」不是位元值：請輸入 ON、OFF、1 或 0</translation>
        </message>
        <message>
            <source>%1 does not fit a 32-bit float (largest about ±%2)</source>
            <translation>%1 超出 32 位元浮點數的範圍（最大約 ±%2）</translation>
        </message>
        <message>
            <source>%1 does not fit a 64-bit double (largest about ±%2)</source>
            <translation>%1 超出 64 位元倍精度浮點數的範圍（最大約 ±%2）</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is too long: %2 holds %3 ASCII characters</source>
            <translation>「%1」太長：%2最多容納 %3 個 ASCII 字元</translation>
        </message>
        <message>
            <source>&quot;%1&quot; contains a character that is not plain printable ASCII (letters, digits, punctuation and space only)</source>
            <translation>「%1」含有不是可列印 ASCII 的字元（只能使用字母、數字、標點符號與空白）</translation>
        </message>
        <message>
            <source>a bit</source>
            <translation>單一位元</translation>
        </message>
        <message>
            <source>a 16-bit register</source>
            <translation>16 位元暫存器</translation>
        </message>
        <message>
            <source>a %1-bit value</source>
            <translation>%1 位元數值</translation>
        </message>
        <message>
            <source>A %1-bit value cannot be written (only 1, 16, 32 or 64 bits).</source>
            <translation>無法寫入 %1 位元的數值（只支援 1、16、32 或 64 位元）。</translation>
        </message>
        <message>
            <source>No value typed: type ON, OFF, 1 or 0.</source>
            <translation>未輸入數值：請輸入 ON、OFF、1 或 0。</translation>
        </message>
        <message>
            <source>No value typed: type a number such as 12, -5, 0x1A or 1Ah.</source>
            <translation>未輸入數值：請輸入數字，例如 12、-5、0x1A 或 1Ah。</translation>
        </message>
        <message>
            <source>%1: %2 elements are not available in the FACON protocol (binary protocol only).</source>
            <translation>%1：FACON 通訊協定不支援 %2 元件（僅限二進位協定）。</translation>
        </message>
        <message>
            <source>Value %1 for %2: a discrete takes 0 (OFF) or 1 (ON).</source>
            <translation>%2 的數值 %1：離散點只能是 0（OFF）或 1（ON）。</translation>
        </message>
        <message>
            <source>Value %1 for %2 does not fit a 16-bit register (0..65535).</source>
            <translation>%2 的數值 %1 超出 16 位元暫存器的範圍（0..65535）。</translation>
        </message>
        <message>
            <source>%1 needs a discrete (X Y M S T C), not %2.</source>
            <translation>%1 需要離散點（X Y M S T C），而非 %2。</translation>
        </message>
        <message>
            <source>%1: %2 points requested; one request carries 1 to 256 points.</source>
            <translation>%1：要求 %2 點；一個請求可包含 1 到 256 點。</translation>
        </message>
        <message>
            <source>%1 needs a register (R, D, WY, DR, ...), not %2; use discretes commands for single points.</source>
            <translation>%1 需要暫存器（R、D、WY、DR 等），而非 %2；單一點請使用離散點命令。</translation>
        </message>
        <message>
            <source>%1: %2 16-bit registers requested; one request carries 1 to %3.</source>
            <translation>%1：要求 %2 個 16 位元暫存器；一個請求可包含 1 到 %3 個。</translation>
        </message>
        <message>
            <source>%1: %2 32-bit registers requested; one request carries 1 to %3 (32-bit registers count as two words).</source>
            <translation>%1：要求 %2 個 32 位元暫存器；一個請求可包含 1 到 %3 個（32 位元暫存器算兩個字組）。</translation>
        </message>
        <message>
            <source>%1: no element given.</source>
            <translation>%1：未指定元件。</translation>
        </message>
        <message>
            <source>%1: %2 elements; at most %3 words fit in one request.</source>
            <translation>%1：%2 個元件；一個請求最多 %3 個字組。</translation>
        </message>
        <message>
            <source>%1: %2 words requested; at most %3 fit in one request (a discrete or 16-bit element counts 1, a 32-bit element 2).</source>
            <translation>%1：要求 %2 個字組；一個請求最多 %3 個（離散點或 16 位元元件算 1 個，32 位元元件算 2 個）。</translation>
        </message>
        <message>
            <source>Station %1 is not valid: stations are 1 to 254 (0 = broadcast).</source>
            <translation>站號 %1 無效：站號範圍是 1 到 254（0 = 廣播）。</translation>
        </message>
        <message>
            <source>Unknown discrete operation %1.</source>
            <translation>未知的離散點操作 %1。</translation>
        </message>
        <message>
            <source>Mixed write: %1 addresses but %2 values.</source>
            <translation>混合寫入：%1 個位址，卻有 %2 個數值。</translation>
        </message>
        <message>
            <source>Loopback test data is %1 bytes; at most 256 fit in one request.</source>
            <translation>迴路測試資料有 %1 位元組；一個請求最多 256 位元組。</translation>
        </message>
        <message>
            <source>FACON loopback data must be printable ASCII characters.</source>
            <translation>FACON 迴路測試資料必須是可列印的 ASCII 字元。</translation>
        </message>
        <message>
            <source>Program pages (4F/50) exist only in the FACON protocol.</source>
            <translation>程式頁（4F/50）只存在於 FACON 通訊協定。</translation>
        </message>
        <message>
            <source>A program page holds exactly 64 words; %1 given.</source>
            <translation>一個程式頁固定為 64 個字組；目前有 %1 個。</translation>
        </message>
        <message>
            <source>Program words are 16-bit (0..65535).</source>
            <translation>程式字組為 16 位元（0..65535）。</translation>
        </message>
        <message>
            <source>Unknown command code %1.</source>
            <translation>未知的命令碼 %1。</translation>
        </message>
        <message>
            <source>%1: station 0 is broadcast; PLCs do not answer it, so nothing can be read there.</source>
            <translation>%1：站號 0 為廣播，PLC 不會回應，因此無法讀取。</translation>
        </message>
        <message>
            <source>table %1</source>
            <translation>表格 %1</translation>
        </message>
        <message>
            <source>table %1, item %2</source>
            <translation>表格 %1，項目 %2</translation>
        </message>
        <message>
            <source>line %1</source>
            <translation>第 %1 行</translation>
        </message>
        <message>
            <source>Not saved</source>
            <translation>未儲存</translation>
        </message>
        <message>
            <source>%1 items are more than one table holds (at most %2)</source>
            <translation>%1 個項目超過一個表格可容納的數量（最多 %2 個）</translation>
        </message>
        <message>
            <source>Answer to %1: %2</source>
            <translation>對 %1 的回應：%2</translation>
        </message>
        <message>
            <source>expected %1 data characters (%2), got %3.</source>
            <translation>預期 %1 個資料字元（%2），收到 %3 個。</translation>
        </message>
        <message>
            <source>status byte &quot;%1&quot; is not hex.</source>
            <translation>狀態位元組「%1」不是十六進位。</translation>
        </message>
        <message>
            <source>discrete status &quot;%1&quot; is not 0 or 1.</source>
            <translation>離散點狀態「%1」不是 0 或 1。</translation>
        </message>
        <message>
            <source>value &quot;%1&quot; is not hex.</source>
            <translation>數值「%1」不是十六進位。</translation>
        </message>
        <message>
            <source>status bytes have an odd number of hex characters (%1).</source>
            <translation>狀態位元組的十六進位字元數為奇數（%1）。</translation>
        </message>
        <message>
            <source>the echoed %1 bytes differ from the %2 bytes sent.</source>
            <translation>回送的 %1 位元組與送出的 %2 位元組不同。</translation>
        </message>
        <message>
            <source>the error byte is missing.</source>
            <translation>缺少錯誤碼位元組。</translation>
        </message>
        <message>
            <source>%1 data bytes instead of %2 (%3).</source>
            <translation>資料有 %1 位元組，而非 %2（%3）。</translation>
        </message>
        <message>
            <source>value %1 for %2 is neither 00 nor 01.</source>
            <translation>%2 的數值 %1 既不是 00 也不是 01。</translation>
        </message>
        <message>
            <source>Answer from station %1 while station %2 was asked (%3).</source>
            <translation>收到站號 %1 的回應，但詢問的是站號 %2（%3）。</translation>
        </message>
        <message>
            <source>Answer to command %1 while %2 (%3) was sent.</source>
            <translation>收到命令 %1 的回應，但送出的是 %2（%3）。</translation>
        </message>
        <message>
            <source>Answer to command %1 while %2 was sent (%3).</source>
            <translation>收到命令 %1 的回應，但送出的是 %2（%3）。</translation>
        </message>
        <message>
            <source>Loopback data differs: sent &quot;%1&quot;, received &quot;%2&quot;.</source>
            <translation>迴路測試資料不同：送出「%1」，收到「%2」。</translation>
        </message>
        <message>
            <source>Answer to %1 has no error digit.</source>
            <translation>對 %1 的回應缺少錯誤碼字元。</translation>
        </message>
        <message>
            <source>Answer to %1: error digit &quot;%2&quot; is not hex.</source>
            <translation>對 %1 的回應：錯誤碼字元「%2」不是十六進位。</translation>
        </message>
        <message>
            <source>%1: %2 data characters; a FACON frame carries at most 500.</source>
            <translation>%1：%2 個資料字元；一個 FACON 訊框最多 500 個。</translation>
        </message>
        <message>
            <source>Received a query frame (51) instead of an answer (52): probably the echo of our own query.</source>
            <translation>收到查詢訊框（51）而非回應（52）：可能是本程式查詢的回音。</translation>
        </message>
        <message>
            <source>FACON frame too short (%1 bytes; at least 8: STX, station, command, LRC, ETX).</source>
            <translation>FACON 訊框太短（%1 位元組；至少 8 位元組：STX、站號、命令、LRC、ETX）。</translation>
        </message>
        <message>
            <source>FACON frame too long (%1 bytes; at most %2).</source>
            <translation>FACON 訊框太長（%1 位元組；最多 %2）。</translation>
        </message>
        <message>
            <source>FACON frame does not start with STX.</source>
            <translation>FACON 訊框不是以 STX 開頭。</translation>
        </message>
        <message>
            <source>FACON frame does not end with ETX.</source>
            <translation>FACON 訊框不是以 ETX 結尾。</translation>
        </message>
        <message>
            <source>FACON frame contains a stray STX or ETX inside.</source>
            <translation>FACON 訊框中間含有多餘的 STX 或 ETX。</translation>
        </message>
        <message>
            <source>FACON frame header &quot;%1&quot; is not station and command in hex.</source>
            <translation>FACON 訊框標頭「%1」不是十六進位的站號與命令。</translation>
        </message>
        <message>
            <source>FACON checksum &quot;%1&quot; is not two hex characters.</source>
            <translation>FACON 檢查碼「%1」不是兩個十六進位字元。</translation>
        </message>
        <message>
            <source>FACON checksum error: frame says %1, computed %2.</source>
            <translation>FACON 檢查碼錯誤：訊框中為 %1，計算結果為 %2。</translation>
        </message>
        <message>
            <source>FACON frame too short (%1 bytes): station, command and LRC do not fit.</source>
            <translation>FACON 訊框太短（%1 位元組）：容納不下站號、命令與 LRC。</translation>
        </message>
        <message>
            <source>FACON frame with a non-hex station or command.</source>
            <translation>FACON 訊框的站號或命令不是十六進位。</translation>
        </message>
        <message>
            <source>FACON frame whose checksum is not two hex characters.</source>
            <translation>FACON 訊框的檢查碼不是兩個十六進位字元。</translation>
        </message>
        <message>
            <source>Incomplete FACON frame: a new STX arrived before ETX.</source>
            <translation>不完整的 FACON 訊框：在 ETX 之前收到新的 STX。</translation>
        </message>
        <message>
            <source>FACON frame without ETX within %1 bytes.</source>
            <translation>FACON 訊框在 %1 位元組內沒有 ETX。</translation>
        </message>
        <message>
            <source>Binary frame too short (%1 bytes): a frame has at least 10 bytes.</source>
            <translation>二進位訊框太短（%1 位元組）：訊框至少有 10 位元組。</translation>
        </message>
        <message>
            <source>Binary frame starts with %1 instead of 51 (query) or 52 (answer).</source>
            <translation>二進位訊框以 %1 開頭，而非 51（查詢）或 52（回應）。</translation>
        </message>
        <message>
            <source>Binary frame ID is %1 instead of 10.</source>
            <translation>二進位訊框 ID 為 %1，而非 10。</translation>
        </message>
        <message>
            <source>Binary frame length field says %1 payload bytes but the frame carries %2.</source>
            <translation>二進位訊框的長度欄位表示 %1 個資料位元組，但訊框帶有 %2 個。</translation>
        </message>
        <message>
            <source>Binary frame ends with %1 instead of the terminator 55 AA.</source>
            <translation>二進位訊框以 %1 結尾，而非正確的結束碼。</translation>
        </message>
        <message>
            <source>Binary frame CRC is %1, computed %2.</source>
            <translation>二進位訊框 CRC 為 %1，計算結果為 %2。</translation>
        </message>
        <message>
            <source>Binary frame without station and command.</source>
            <translation>二進位訊框缺少站號與命令。</translation>
        </message>
        <message>
            <source>Binary frame of %1 bytes does not end with the terminator 55 AA.</source>
            <translation>%1 位元組的二進位訊框沒有以正確的結束碼結尾。</translation>
        </message>
        <message>
            <source>Binary frame of %1 bytes has a wrong CRC (line noise or a broken frame).</source>
            <translation>%1 位元組的二進位訊框 CRC 錯誤（線路雜訊或訊框損壞）。</translation>
        </message>
        <message>
            <source>%1 series, %2-word program</source>
            <translation>%1 系列，%2 字組程式</translation>
        </message>
        <message>
            <source>Cannot read the program backup %1: %2</source>
            <translation>無法讀取程式備份 %1：%2</translation>
        </message>
        <message>
            <source>Cannot write the program backup %1: %2</source>
            <translation>無法寫入程式備份 %1：%2</translation>
        </message>
        <message>
            <source>The program backup is not valid JSON: %1</source>
            <translation>程式備份不是有效的 JSON：%1</translation>
        </message>
        <message>
            <source>The file is not a program backup (format &quot;%1&quot;, expected &quot;fatek-program&quot;).</source>
            <translation>此檔案不是程式備份（其格式為「%1」）。</translation>
        </message>
        <message>
            <source>The program backup has format version %1, which this program cannot read.</source>
            <translation>程式備份的格式版本為 %1，本程式無法讀取。</translation>
        </message>
        <message>
            <source>The program backup is damaged: the field &quot;%1&quot; is missing or wrong.</source>
            <translation>程式備份已損壞：欄位「%1」遺失或錯誤。</translation>
        </message>
        <message>
            <source>The program backup is damaged or truncated: it holds %1 pages, its header needs %2.</source>
            <translation>程式備份已損壞或不完整：內含 %1 頁，其標頭需要 %2 頁。</translation>
        </message>
        <message>
            <source>The program backup is damaged: page %1 is not 64 words of 4 hex digits.</source>
            <translation>程式備份已損壞：第 %1 頁不是 64 個 4 位十六進位字組。</translation>
        </message>
        <message>
            <source>The program backup is damaged: its checksum is %1, its words give %2.</source>
            <translation>程式備份已損壞：其檢查碼為 %1，字組計算結果為 %2。</translation>
        </message>
        <message>
            <source>The program backup is damaged: page 0 is not a program header.</source>
            <translation>程式備份已損壞：第 0 頁不是程式標頭。</translation>
        </message>
        <message>
            <source>No connection to a PLC.</source>
            <translation>沒有與 PLC 的連線。</translation>
        </message>
        <message>
            <source>A program transfer is already running.</source>
            <translation>已有程式傳輸正在進行。</translation>
        </message>
        <message>
            <source>Operator mode: restoring a program is refused; nothing was written.</source>
            <translation>操作員模式：拒絕還原程式；未寫入任何資料。</translation>
        </message>
        <message>
            <source>The PLC is in RUN: switch it to STOP before restoring a program; nothing was written.</source>
            <translation>PLC 處於 RUN：還原程式前請先切換至 STOP；未寫入任何資料。</translation>
        </message>
        <message>
            <source>The PLC did not report its program size (detail status 53).</source>
            <translation>PLC 未回報其程式容量（詳細狀態 53）。</translation>
        </message>
        <message>
            <source>The PLC's page 0 is not a program header.</source>
            <translation>PLC 的第 0 頁不是程式標頭。</translation>
        </message>
        <message>
            <source>The backup is for a %1, the PLC holds a %2: not restored, nothing was written.</source>
            <translation>此備份適用於 %1，PLC 為 %2：未還原，未寫入任何資料。</translation>
        </message>
        <message>
            <source>%1 with a %2-word program</source>
            <translation>%1，程式容量 %2 字組</translation>
        </message>
        <message>
            <source>%1-word program (the PLC does not name its model)</source>
            <translation>%1 字組程式（PLC 未提供機型）</translation>
        </message>
        <message>
            <source>Reading program page %1 failed: %2</source>
            <translation>讀取程式第 %1 頁失敗：%2</translation>
        </message>
        <message>
            <source>Writing program page %1 failed: %2</source>
            <translation>寫入程式第 %1 頁失敗：%2</translation>
        </message>
        <message>
            <source>%1 The PLC now holds a mixed program (%2 of %3 {3:page|pages} written from the backup, the rest from its old program) and stays in STOP: restore the same file again before switching it to RUN.</source>
            <translation>%1 PLC 目前的程式新舊混合（%3 頁中已由備份寫入 %2 頁，其餘仍為舊程式），並維持在 STOP：請先以同一個檔案再還原一次，再切換到 RUN。</translation>
        </message>
        <message>
            <source>Verification failed: %1 {1:page|pages} on the PLC {1:differs|differ} from the backup (%2).</source>
            <translation>驗證失敗：PLC 上有 %1 頁與備份不同（%2）。</translation>
        </message>
        <message>
            <source>Backup cancelled at page %1 (%2 of %3 {3:page|pages} read); no file saved.</source>
            <translation>備份已於第 %1 頁取消（已讀取 %2／%3 頁）；未儲存檔案。</translation>
        </message>
        <message>
            <source>Restore cancelled at page %1 (%2 of %3 {3:page|pages} written): the PLC's program is incomplete.</source>
            <translation>還原已於第 %1 頁取消（已寫入 %2／%3 頁）：PLC 的程式不完整。</translation>
        </message>
        <message>
            <source>Cancelled before anything was written.</source>
            <translation>已在寫入任何資料前取消。</translation>
        </message>
        <message>
            <source>Backup done: %1 {1:page|pages} of a %2.</source>
            <translation>備份完成：%2 的 %1 頁。</translation>
        </message>
        <message>
            <source>Restore done: %1 {1:page|pages} written and verified.</source>
            <translation>還原完成：已寫入並驗證 %1 頁。</translation>
        </message>
        <message>
            <source>%1 {1:page differs|pages differ} from the PLC (%2).</source>
            <translation>%1 頁與 PLC 不同（%2）。</translation>
        </message>
        <message>
            <source>The PLC already holds this program.</source>
            <translation>PLC 已存有此程式。</translation>
        </message>
        <message>
            <source>Reading the program</source>
            <translation>正在讀取程式</translation>
        </message>
        <message>
            <source>Writing the program</source>
            <translation>正在寫入程式</translation>
        </message>
        <message>
            <source>Reading the program back to verify</source>
            <translation>正在讀回程式以驗證</translation>
        </message>
        <message>
            <source>Verification cancelled at page %1 (%2 of %3 {3:page|pages} checked); the program was written completely.</source>
            <translation>驗證已於第 %1 頁取消（已檢查 %2／%3 頁）；程式已完整寫入。</translation>
        </message>
        <message>
            <source>No connection to read from.</source>
            <translation>沒有可讀取的連線。</translation>
        </message>
        <message>
            <source>A snapshot or restore is already running.</source>
            <translation>已有快照或還原正在執行。</translation>
        </message>
        <message>
            <source>The PLC did not report its memory sizes (%1): give the ranges to read.</source>
            <translation>PLC 未回報其記憶體大小（%1）：請指定要讀取的範圍。</translation>
        </message>
        <message>
            <source>No element ranges to read.</source>
            <translation>沒有要讀取的元件範圍。</translation>
        </message>
        <message>
            <source>%1 elements are more than a snapshot holds (at most %2).</source>
            <translation>%1 個元件超過快照可容納的數量（最多 %2 個）。</translation>
        </message>
        <message>
            <source>Cannot read %1: %2</source>
            <translation>無法讀取 %1：%2</translation>
        </message>
        <message>
            <source>The file is not UTF-8 text, and this build cannot decode Big5.</source>
            <translation>檔案不是萬國碼文字，而此版本無法解碼大五碼。</translation>
        </message>
        <message>
            <source>the line is neither UTF-8 nor Big5 text</source>
            <translation>此行既不是萬國碼也不是大五碼文字</translation>
        </message>
        <message>
            <source>no address in the first column</source>
            <translation>第一欄沒有位址</translation>
        </message>
        <message>
            <source>%1 has neither a name nor a comment</source>
            <translation>%1 既沒有名稱也沒有註解</translation>
        </message>
        <message>
            <source>a quoted field is not closed on its line (missing &quot;)</source>
            <translation>引號欄位未在同一行內結束（缺少 &quot;)</translation>
        </message>
        <message>
            <source>text after the quoted field &quot;%1&quot;</source>
            <translation>引號欄位「%1」之後還有文字</translation>
        </message>
        <message>
            <source>Names imported: %1, lines skipped: %2</source>
            <translation>已匯入名稱：%1，略過的行：%2</translation>
        </message>
        <message>
            <source>Names imported: %1, lines skipped: %2 (%3)</source>
            <translation>已匯入名稱：%1，略過的行：%2（%3）</translation>
        </message>
        <message>
            <source>and %1 more</source>
            <translation>另有 %1 行</translation>
        </message>
        <message>
            <source>%1; read as Big5</source>
            <translation>%1；以大五碼讀取</translation>
        </message>
        <message>
            <source>symbol %1</source>
            <translation>符號 %1</translation>
        </message>
        <message>
            <source>Cancelled.</source>
            <translation>已取消。</translation>
        </message>
        <message>
            <source>%1 {1:value|values} read in %2 {2:request|requests}.</source>
            <translation>以 %2 次請求讀取了 %1 個值。</translation>
        </message>
        <message>
            <source>value %1</source>
            <translation>第 %1 個值</translation>
        </message>
        <message>
            <source>line %1, column %2</source>
            <translation>第 %1 行，第 %2 欄</translation>
        </message>
        <message>
            <source>%1: a snapshot file name ends in .json or .csv.</source>
            <translation>%1：快照檔名須為 *.json 或 *.csv。</translation>
        </message>
        <message>
            <source>Cannot open %1: %2</source>
            <translation>無法開啟 %1：%2</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>無法寫入 %1：%2</translation>
        </message>
        <message>
            <source>not valid JSON (%1)</source>
            <translation>不是有效的 *.json 內容（%1）</translation>
        </message>
        <message>
            <source>not a memory snapshot (&quot;format&quot; is not &quot;%1&quot;)</source>
            <translation>不是記憶體快照（格式標記不是「%1」）</translation>
        </message>
        <message>
            <source>snapshot version %1 is not supported (this program reads %2)</source>
            <translation>不支援快照版本 %1（本程式讀取版本 %2）</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is missing</source>
            <translation>缺少 &quot;%1&quot;</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a whole number</source>
            <translation>&quot;%1&quot; 不是整數</translation>
        </message>
        <message>
            <source>%1 does not fit %2 (0..%3)</source>
            <translation>%1 超出 %2 的範圍（0..%3）</translation>
        </message>
        <message>
            <source>the hex column %1 differs from the value %2</source>
            <translation>十六進位欄 %1 與數值 %2 不符</translation>
        </message>
        <message>
            <source>%1 appears twice</source>
            <translation>%1 重複出現</translation>
        </message>
        <message>
            <source>expected address,value[,hex]</source>
            <translation>應為位址、數值（及選用的十六進位）欄位</translation>
        </message>
        <message>
            <source>a metadata line reads &quot;# key: value&quot;</source>
            <translation>中繼資料行的格式為「# 名稱: 內容」</translation>
        </message>
        <message>
            <source>the snapshot holds no values</source>
            <translation>快照中沒有任何值</translation>
        </message>
        <message>
            <source>(absent)</source>
            <translation>（無）</translation>
        </message>
        <message>
            <source>%1: %2 -&gt; %3</source>
            <translation>%1：%2 → %3</translation>
        </message>
        <message>
            <source>No differences.</source>
            <translation>沒有差異。</translation>
        </message>
        <message>
            <source>%1 of %2 {2:value|values} {1:differs|differ}.</source>
            <translation>%2 個值中有 %1 個不同。</translation>
        </message>
        <message>
            <source>Operator mode: restoring values is refused; nothing was written.</source>
            <translation>操作員模式：拒絕還原數值，未寫入任何資料。</translation>
        </message>
        <message>
            <source>The chosen ranges hold no value of the snapshot: nothing to write.</source>
            <translation>所選範圍內沒有快照中的值：沒有要寫入的資料。</translation>
        </message>
        <message>
            <source>Writing %1 failed: %2</source>
            <translation>寫入 %1 失敗：%2</translation>
        </message>
        <message>
            <source>%1 %2 of %3 {3:value|values} had been written when it stopped; the others may still hold their old values: restore the same file again.</source>
            <translation>%1 停止時 %3 個數值中已寫入 %2 個；其餘可能仍是舊值：請以同一個檔案再還原一次。</translation>
        </message>
        <message>
            <source>Reading the values back failed: %1</source>
            <translation>回讀數值失敗：%1</translation>
        </message>
        <message>
            <source>%1 of %2 {2:value|values} {1:differs|differ} after the write (read back).</source>
            <translation>寫入後回讀，%2 個值中有 %1 個不同。</translation>
        </message>
        <message>
            <source>%1 {1:value|values} written in %2 {2:request|requests} and read back equal.</source>
            <translation>以 %2 次請求寫入 %1 個值，回讀結果一致。</translation>
        </message>
        <message>
            <source>The snapshot is of another model (%1) than the PLC (%2): not restored, nothing was written.</source>
            <translation>快照的機型（%1）與 PLC（%2）不同：未還原，未寫入任何資料。</translation>
        </message>
        <message>
            <source>%2 {2:value|values} of the snapshot {2:is|are} not on the PLC: %1. The PLC (%3) has %4. Not restored, nothing was written.</source>
            <translation>快照中有 %2 個值是 PLC 沒有的元件：%1。此 PLC（%3）只有 %4。未還原，未寫入任何資料。</translation>
        </message>
        <message>
            <source>Reading the PLC's model and ranges failed (%1): nothing was written.</source>
            <translation>讀取 PLC 的機型與元件範圍失敗（%1）：未寫入任何資料。</translation>
        </message>
        <message>
            <source>%1 cannot be checked: a checkout takes inputs X, outputs Y and registers R or D.</source>
            <translation>%1 無法檢查：點檢只接受輸入 X、輸出 Y 及暫存器 R 或 D。</translation>
        </message>
        <message>
            <source>The checkout plan holds no points.</source>
            <translation>點檢計畫中沒有任何點。</translation>
        </message>
        <message>
            <source>%1 appears twice in the checkout plan.</source>
            <translation>%1 在點檢計畫中出現兩次。</translation>
        </message>
        <message>
            <source>No imported name of an input or output starts with &quot;%1&quot;.</source>
            <translation>沒有以「%1」開頭的輸入或輸出匯入名稱。</translation>
        </message>
        <message>
            <source>checkout plan line %1: %2</source>
            <translation>點檢計畫第 %1 行：%2</translation>
        </message>
        <message>
            <source>expected the columns %1</source>
            <translation>應有的欄位為 %1</translation>
        </message>
        <message>
            <source>%1: an analog point needs its expected low and high values</source>
            <translation>%1：類比點需要預期的低端與高端值</translation>
        </message>
        <message>
            <source>Cannot open the checkout %1: %2</source>
            <translation>無法開啟點檢檔 %1：%2</translation>
        </message>
        <message>
            <source>Cannot save the checkout %1: %2</source>
            <translation>無法儲存點檢檔 %1：%2</translation>
        </message>
        <message>
            <source>The checkout %1 is damaged: %2</source>
            <translation>點檢檔 %1 已損壞：%2</translation>
        </message>
        <message>
            <source>not a checkout (&quot;format&quot; is not &quot;%1&quot;)</source>
            <translation>不是點檢檔（格式標記不是「%1」）</translation>
        </message>
        <message>
            <source>No connection to a PLC: the checkout waits.</source>
            <translation>未連線到 PLC：點檢等待中。</translation>
        </message>
        <message>
            <source>Operator mode: testing outputs is refused; nothing was forced.</source>
            <translation>操作員模式：拒絕測試輸出；未強制任何點。</translation>
        </message>
        <message>
            <source>%1 is still under test: answer for it before the next output.</source>
            <translation>%1 仍在測試中：請先回答它，再測下一個輸出。</translation>
        </message>
        <message>
            <source>%1 is not an output of the checkout plan.</source>
            <translation>%1 不是點檢計畫中的輸出。</translation>
        </message>
        <message>
            <source>%1 changed while testing %2: crossed wiring?</source>
            <translation>測試 %2 時 %1 發生變化：配線交錯？</translation>
        </message>
        <message>
            <source>The PLC is in RUN: its program drives the outputs too. Force %1 on anyway? Yes: %1 and then each output tested is forced on until its answer, whatever the program does. No: nothing is forced.</source>
            <translation>PLC 處於 RUN：其程式也在驅動輸出。仍要強制 %1 導通嗎？是：%1 及之後測試的每個輸出都會強制導通直到回答為止，不受程式影響。否：不強制任何點。</translation>
        </message>
        <message>
            <source>Not forced: the PLC is in RUN and forcing was not confirmed. The outputs stay untested.</source>
            <translation>未強制：PLC 處於 RUN 且未確認強制。這些輸出維持未測試。</translation>
        </message>
        <message>
            <source>Forcing %1 failed: %2</source>
            <translation>強制 %1 失敗：%2</translation>
        </message>
        <message>
            <source>Releasing %1 failed: %2. It stays recorded as forced; the release is tried again until the PLC confirms it.</source>
            <translation>解除 %1 失敗：%2。它仍記錄為已強制；將持續重試解除，直到 PLC 確認為止。</translation>
        </message>
        <message>
            <source>%1 is not released yet (the PLC has not confirmed it): it is forced again only after that.</source>
            <translation>%1 尚未解除（PLC 尚未確認）：確認解除後才能再次強制。</translation>
        </message>
        <message>
            <source>Released the outputs the checkout had forced: %1.</source>
            <translation>已解除點檢先前強制的輸出：%1。</translation>
        </message>
        <message>
            <source>The link is lost: a forced output is released as soon as it is back.</source>
            <translation>連線中斷：連線恢復後將立即解除已強制的輸出。</translation>
        </message>
        <message>
            <source>Reading %1 failed: %2</source>
            <translation>讀取 %1 失敗：%2</translation>
        </message>
        <message>
            <source>Input</source>
            <translation>輸入</translation>
        </message>
        <message>
            <source>Output</source>
            <translation>輸出</translation>
        </message>
        <message>
            <source>Analog</source>
            <translation>類比</translation>
        </message>
        <message>
            <source>Untested</source>
            <translation>未測試</translation>
        </message>
        <message>
            <source>Passed</source>
            <translation>合格</translation>
        </message>
        <message>
            <source>Failed</source>
            <translation>不合格</translation>
        </message>
        <message>
            <source>0-&gt;1 at %1, 1-&gt;0 at %2</source>
            <translation>0-&gt;1 於 %1，1-&gt;0 於 %2</translation>
        </message>
        <message>
            <source>seen in the field</source>
            <translation>現場已確認</translation>
        </message>
        <message>
            <source>not seen in the field</source>
            <translation>現場未見動作</translation>
        </message>
        <message>
            <source>also changed while it was tested: %1</source>
            <translation>測試期間同時變化：%1</translation>
        </message>
        <message>
            <source>I/O checkout report</source>
            <translation>I/O 點檢報告</translation>
        </message>
        <message>
            <source>Project</source>
            <translation>專案</translation>
        </message>
        <message>
            <source>Customer</source>
            <translation>客戶</translation>
        </message>
        <message>
            <source>PLC model</source>
            <translation>PLC 機型</translation>
        </message>
        <message>
            <source>OS version</source>
            <translation>OS 版本</translation>
        </message>
        <message>
            <source>PLC station</source>
            <translation>PLC 站號</translation>
        </message>
        <message>
            <source>Date</source>
            <translation>日期</translation>
        </message>
        <message>
            <source>Engineer</source>
            <translation>工程師</translation>
        </message>
        <message>
            <source>not reported by the PLC</source>
            <translation>PLC 未回報</translation>
        </message>
        <message>
            <source>Point</source>
            <translation>點位</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>名稱</translation>
        </message>
        <message>
            <source>Group</source>
            <translation>群組</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>類型</translation>
        </message>
        <message>
            <source>Result</source>
            <translation>結果</translation>
        </message>
        <message>
            <source>Measured</source>
            <translation>量測</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>備註</translation>
        </message>
        <message>
            <source>Tested at</source>
            <translation>測試時間</translation>
        </message>
        <message>
            <source>Summary</source>
            <translation>摘要</translation>
        </message>
        <message>
            <source>Signatures</source>
            <translation>簽名</translation>
        </message>
        <message>
            <source>Commissioning engineer</source>
            <translation>試車工程師</translation>
        </message>
        <message>
            <source>Customer representative</source>
            <translation>客戶代表</translation>
        </message>
        <message>
            <source>Witness</source>
            <translation>見證人</translation>
        </message>
        <message>
            <source>Role</source>
            <translation>身分</translation>
        </message>
        <message>
            <source>Printed name</source>
            <translation>姓名（正楷）</translation>
        </message>
        <message>
            <source>Company</source>
            <translation>公司</translation>
        </message>
        <message>
            <source>Signature</source>
            <translation>簽名</translation>
        </message>
        <message>
            <source>Tested</source>
            <translation>測試期間</translation>
        </message>
        <message>
            <source>%1 to %2</source>
            <translation>%1 至 %2</translation>
        </message>
        <message>
            <source>nothing recorded yet</source>
            <translation>尚無紀錄</translation>
        </message>
        <message>
            <source>Report made</source>
            <translation>報告產生時間</translation>
        </message>
        <message>
            <source>%1 (%2 {2:point|points})</source>
            <translation>%1（%2 點）</translation>
        </message>
        <message>
            <source>not named</source>
            <translation>未填姓名</translation>
        </message>
        <message>
            <source>Page %1 of %2</source>
            <translation>第 %1 頁，共 %2 頁</translation>
        </message>
        <message>
            <source>Results</source>
            <translation>測試結果</translation>
        </message>
        
        <message>
            <source>Not tested (%1): %2</source>
            <translation>未測試（%1 點）：%2</translation>
        </message>
        <message>
            <source>Cannot write the report %1: %2</source>
            <translation>無法寫入報告 %1：%2</translation>
        </message>
        <message>
            <source>%1: a report file name ends in .pdf or .csv.</source>
            <translation>%1：報告檔名須以 *.pdf 或 *.csv 結尾。</translation>
        </message>
        <message>
            <source>No broker given.</source>
            <translation>未指定代理伺服器。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a broker address: write mqtt://host:1883 or mqtts://user@host:8883.</source>
            <translation>「%1」不是代理伺服器位址：請寫成 mqtt://host:1883 或 mqtts://user@host:8883。</translation>
        </message>
        <message>
            <source>refused a command on &quot;%1&quot;: %2</source>
            <translation>拒絕主題「%1」上的命令：%2</translation>
        </message>
        <message>
            <source>station %1 does not answer: %2</source>
            <translation>站號 %1 沒有回應：%2</translation>
        </message>
        <message>
            <source>station %1 demoted: %2</source>
            <translation>站號 %1 已降級：%2</translation>
        </message>
        <message>
            <source>station %1 answers again</source>
            <translation>站號 %1 恢復回應</translation>
        </message>
        <message>
            <source>station %1 %2: %3</source>
            <translation>站號 %1 %2：%3</translation>
        </message>
        <message>
            <source>station %1 %2 read again</source>
            <translation>站號 %1 %2 恢復讀取</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a host: write an IP address (192.168.1.5) or a host name (letters, digits, &apos;-&apos; and &apos;.&apos;).</source>
            <translation>「%1」不是主機：請寫 IP 位址（192.168.1.5）或主機名稱（字母、數字、&apos;-&apos; 與 &apos;.&apos;）。</translation>
        </message>
        <message>
            <source>Connections &quot;%1&quot; and &quot;%2&quot; would get the same Home Assistant id &quot;%3&quot; (characters other than letters, digits, &apos;-&apos; and &apos;_&apos; become &apos;_&apos;): rename one.</source>
            <translation>連線「%1」與「%2」會得到相同的 Home Assistant 識別碼「%3」（字母、數字、&apos;-&apos; 與 &apos;_&apos; 以外的字元都變成 &apos;_&apos;）：請將其中一個改名。</translation>
        </message>
        <message>
            <source>%1 is a TLS setting, but the broker URL is mqtt:// (clear text): write mqtts://, or remove %1.</source>
            <translation>%1 是 TLS 設定，但代理伺服器網址是 mqtt://（明文）：請寫 mqtts://，或移除 %1。</translation>
        </message>
        <message>
            <source>The CA file %1 holds no usable certificate: %2.</source>
            <translation>CA 檔案 %1 沒有可用的憑證：%2。</translation>
        </message>
        <message>
            <source>The certificate file %1 is not usable: %2.</source>
            <translation>憑證檔案 %1 無法使用：%2。</translation>
        </message>
        <message>
            <source>The key file %1 is not usable: %2.</source>
            <translation>金鑰檔案 %1 無法使用：%2。</translation>
        </message>
        <message>
            <source>The key file %1 is not the key of the certificate %2.</source>
            <translation>金鑰檔案 %1 不是憑證 %2 的金鑰。</translation>
        </message>
        <message>
            <source>The broker %1 closed the connection right after accepting it, %2 times in a row: another client with the same client id &quot;%3&quot; took over (a second gateway with this configuration?); trying again less often.</source>
            <translation>代理伺服器 %1 在接受連線後隨即關閉，連續 %2 次：另一個使用相同用戶端識別碼「%3」的用戶端接手了（是否有第二個使用此設定的閘道器？）；將降低重試頻率。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; must be a string.</source>
            <translation>「%1」必須是字串。</translation>
        </message>
        <message>
            <source>Cannot read the TLS file %1.</source>
            <translation>無法讀取 TLS 檔案 %1。</translation>
        </message>
        <message>
            <source>A client certificate needs its key file, and a key its certificate.</source>
            <translation>用戶端憑證需要其金鑰檔，金鑰也需要其憑證。</translation>
        </message>
        <message>
            <source>%1 needs TLS, which this build&apos;s MQTT library does not have (the Windows build has none yet): use an mqtt:// broker.</source>
            <translation>%1 需要 TLS，但此版本的 MQTT 函式庫不支援 TLS（Windows 版目前沒有）：請使用 mqtt:// 代理伺服器。</translation>
        </message>
        <message>
            <source>A broker password needs a user name.</source>
            <translation>代理伺服器密碼需要使用者名稱。</translation>
        </message>
        <message>
            <source>Broker timing out of range: keep-alive at least 5 s, reconnect delays at least 10 ms, the longest not below the first.</source>
            <translation>代理伺服器時間設定超出範圍：保持連線至少 5 秒，重新連線延遲至少 10 毫秒，最長延遲不得小於第一次。</translation>
        </message>
        <message>
            <source>Cannot reach the broker %1: %2</source>
            <translation>無法連線到代理伺服器 %1：%2</translation>
        </message>
        <message>
            <source>the broker closed the connection before accepting it</source>
            <translation>代理伺服器在接受連線前就關閉了連線</translation>
        </message>
        <message>
            <source>%1; the broker may require a client certificate, and none is configured (certFile, keyFile)</source>
            <translation>%1；代理伺服器可能要求用戶端憑證，但尚未設定（{&quot;certFile&quot;: ...}、{&quot;keyFile&quot;: ...}）</translation>
        </message>
        <message>
            <source>the TLS handshake failed</source>
            <translation>TLS 交握失敗</translation>
        </message>
        <message>
            <source>%1 (the library says: %2)</source>
            <translation>%1（函式庫訊息：%2）</translation>
        </message>
        <message>
            <source>The broker %1 refused us: %2</source>
            <translation>代理伺服器 %1 拒絕連線：%2</translation>
        </message>
        <message>
            <source>Link to the broker %1 lost: %2</source>
            <translation>與代理伺服器 %1 的連線中斷：%2</translation>
        </message>
        <message>
            <source>Disconnected from the broker %1.</source>
            <translation>已與代理伺服器 %1 斷線。</translation>
        </message>
        <message>
            <source>keep-alive timeout: the broker did not answer within %1 s</source>
            <translation>保持連線逾時：代理伺服器在 %1 秒內沒有回應</translation>
        </message>
        <message>
            <source>MQTT library error: %1</source>
            <translation>MQTT 程式庫錯誤：%1</translation>
        </message>
        <message>
            <source>The command starts with { but is not a JSON object.</source>
            <translation>命令以 { 開頭，但不是 JSON 物件。</translation>
        </message>
        <message>
            <source>The command has no value: send the text to write, or {&quot;value&quot;: ...}.</source>
            <translation>命令沒有數值：請傳送要寫入的文字，或 {&quot;value&quot;: ...}。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a value format.</source>
            <translation>「%1」不是數值格式。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; must be %2 or %3.</source>
            <translation>「%1」必須為 %2 或 %3。</translation>
        </message>
        <message>
            <source>&quot;words&quot; must be a list of whole numbers from 0 to 4294967295.</source>
            <translation>{&quot;words&quot;: [...]} 必須是 0 到 4294967295 的整數清單。</translation>
        </message>
        <message>
            <source>The command has %1 word(s), but %2 in this format spans %3.</source>
            <translation>命令有 %1 個字組，但 %2 在此格式下佔 %3 個。</translation>
        </message>
        <message>
            <source>&quot;id&quot; must be text or a number.</source>
            <translation>{&quot;id&quot;: ...} 必須是文字或數字。</translation>
        </message>
        <message>
            <source>Refused: the command&apos;s &quot;time&quot; is %1 s ahead of the gateway&apos;s clock (at most %2 s are taken); check the sender&apos;s clock.</source>
            <translation>拒絕：此命令的 {&quot;time&quot;: ...} 比閘道的時鐘快 %1 秒（最多接受 %2 秒）；請檢查發送端的時鐘。</translation>
        </message>
        <message>
            <source>%1 (station %2) is not published by the gateway %3.</source>
            <translation>%1（站號 %2）未由閘道器 %3 發佈。</translation>
        </message>
        <message>
            <source>No status from the gateway %1 yet.</source>
            <translation>尚未收到閘道器 %1 的狀態。</translation>
        </message>
        <message>
            <source>The gateway %1 is connecting to its PLC.</source>
            <translation>閘道器 %1 正在連線至其 PLC。</translation>
        </message>
        <message>
            <source>The gateway %1 is offline.</source>
            <translation>閘道器 %1 已離線。</translation>
        </message>
        <message>
            <source>The gateway %1 is offline: %2</source>
            <translation>閘道器 %1 已離線：%2</translation>
        </message>
        <message>
            <source>The gateway %1 lost its link to the PLC.</source>
            <translation>閘道器 %1 與 PLC 的連線中斷。</translation>
        </message>
        <message>
            <source>The gateway %1 lost its link to the PLC: %2</source>
            <translation>閘道器 %1 與 PLC 的連線中斷：%2</translation>
        </message>
        <message>
            <source>%1 was not sent: %2</source>
            <translation>%1 未送出：%2</translation>
        </message>
        <message>
            <source>The broker %1 did not take the command.</source>
            <translation>代理伺服器 %1 未接受此命令。</translation>
        </message>
        <message>
            <source>No reply from the gateway %1 within %2 s.</source>
            <translation>閘道器 %1 在 %2 秒內未回覆。</translation>
        </message>
        <message>
            <source>The gateway %1 did not write the value.</source>
            <translation>閘道器 %1 未寫入此值。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a topic prefix: levels separated by /, without + or #.</source>
            <translation>「%1」不是主題前綴：各層以 / 分隔，不可含 + 或 #。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a gateway connection name: 1 to 64 letters, digits, -, _ or ., and not a number.</source>
            <translation>「%1」不是閘道器連線名稱：須為 1 至 64 個字母、數字、-、_ 或 .，且不可為純數字。</translation>
        </message>
        <message>
            <source>The configuration is not a JSON object: %1</source>
            <translation>設定不是 JSON 物件：%1</translation>
        </message>
        <message>
            <source>Not a gateway configuration: &quot;%1&quot; must be &quot;%2&quot;.</source>
            <translation>不是閘道設定：&quot;%1&quot; 必須是 &quot;%2&quot;。</translation>
        </message>
        <message>
            <source>Configuration version %1 is not supported (this program reads version %2).</source>
            <translation>不支援設定版本 %1（本程式讀取版本 %2）。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is missing.</source>
            <translation>缺少 &quot;%1&quot;。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; must be %2.</source>
            <translation>&quot;%1&quot; 必須是%2。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a known setting.</source>
            <translation>&quot;%1&quot; 不是已知的設定。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a known setting; did you mean &quot;%2&quot;?</source>
            <translation>&quot;%1&quot; 不是已知的設定；您是指 &quot;%2&quot; 嗎？</translation>
        </message>
        <message>
            <source>a string</source>
            <translation>字串</translation>
        </message>
        <message>
            <source>a whole number</source>
            <translation>整數</translation>
        </message>
        <message>
            <source>%1 or %2</source>
            <translation>%1 或 %2</translation>
        </message>
        <message>
            <source>a list</source>
            <translation>清單</translation>
        </message>
        <message>
            <source>an object</source>
            <translation>物件</translation>
        </message>
        <message>
            <source>%1 %2 is out of range (%3..%4)</source>
            <translation>%1 %2 超出範圍（%3..%4）</translation>
        </message>
        <message>
            <source>No connections: the configuration needs at least one.</source>
            <translation>沒有連線：設定至少需要一個。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a usable connection name: 1 to 64 letters, digits, &apos;-&apos;, &apos;_&apos; or &apos;.&apos;, and not a number.</source>
            <translation>&quot;%1&quot; 不是可用的連線名稱：1 到 64 個字母、數字、&apos;-&apos;、&apos;_&apos; 或 &apos;.&apos;，且不可只是數字。</translation>
        </message>
        <message>
            <source>The connection name &quot;%1&quot; is used twice.</source>
            <translation>連線名稱 &quot;%1&quot; 重複使用。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a usable topic prefix: levels separated by &apos;/&apos;, none empty, without &apos;+&apos;, &apos;#&apos; or a NUL character, not starting with &apos;$&apos;.</source>
            <translation>&quot;%1&quot; 不是可用的主題前綴：以 &apos;/&apos; 分隔層級，不可為空，不可含 &apos;+&apos;、&apos;#&apos; 或 NUL 字元，不可以 &apos;$&apos; 開頭。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a link kind: write %2, %3 or %4.</source>
            <translation>&quot;%1&quot; 不是連線類型：請寫 %2、%3 或 %4。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a protocol: write %2, %3 or %4.</source>
            <translation>&quot;%1&quot; 不是通訊協定：請寫 %2、%3 或 %4。</translation>
        </message>
        <message>
            <source>Nothing to watch: give at least one watch list with items.</source>
            <translation>沒有可監看的項目：請至少提供一個含項目的監看清單。</translation>
        </message>
        <message>
            <source>station %1 %2 is watched twice (each address has one topic)</source>
            <translation>站號 %1 %2 被監看兩次（每個位址只有一個主題）</translation>
        </message>
        <message>
            <source>Give the broker &quot;%1&quot; or a &quot;%2&quot;, not both.</source>
            <translation>請提供代理伺服器的 &quot;%1&quot; 或 &quot;%2&quot;，不可兩者皆有。</translation>
        </message>
        <message>
            <source>connection %1 (%2)</source>
            <translation>連線 %1（%2）</translation>
        </message>
        <message>
            <source>connection %1</source>
            <translation>連線 %1</translation>
        </message>
        <message>
            <source>link</source>
            <translation>連線設定</translation>
        </message>
        <message>
            <source>broker</source>
            <translation>代理伺服器</translation>
        </message>
        <message>
            <source>watch list %1</source>
            <translation>監看清單 %1</translation>
        </message>
        <message>
            <source>allow &quot;%1&quot;</source>
            <translation>允許 &quot;%1&quot;</translation>
        </message>
        <message>
            <source>not read in this cycle</source>
            <translation>本週期未讀取</translation>
        </message>
        <message>
            <source>duplicate key &quot;%1&quot;</source>
            <translation>「%1」鍵重複出現</translation>
        </message>
        <message>
            <source>There is no alarm %1.</source>
            <translation>沒有警報 %1。</translation>
        </message>
        <message>
            <source>Alarm %1 has nothing to acknowledge (it is not unacknowledged).</source>
            <translation>警報 %1 沒有需要確認的事項（它不是未確認狀態）。</translation>
        </message>
        <message>
            <source>Alarm %1 is not shelved.</source>
            <translation>警報 %1 未被擱置。</translation>
        </message>
        <message>
            <source>Alarm %1 cannot be shelved until a time that has passed.</source>
            <translation>警報 %1 不能擱置到已經過去的時間。</translation>
        </message>
        <message>
            <source>Alarm %1 is out of service (disabled in its definition).</source>
            <translation>警報 %1 已停用（在其定義中停用）。</translation>
        </message>
        <message>
            <source>Refused: no alarm &quot;%1&quot; on this connection.</source>
            <translation>已拒絕：此連線沒有警報「%1」。</translation>
        </message>
        <message>
            <source>Refused: a retained alarm command would be carried out again at every restart; publish it without the retain flag.</source>
            <translation>已拒絕：保留的警報命令會在每次重新啟動時再次執行；請不帶保留旗標發布。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is not a key of this alarm command (it takes %2).</source>
            <translation>「%1」不是此警報命令的鍵（它接受 %2）。</translation>
        </message>
        <message>
            <source>&quot;%1&quot; must be text.</source>
            <translation>「%1」必須是文字。</translation>
        </message>
        <message>
            <source>A shelve needs &quot;until&quot; (ISO 8601 with its offset, ahead of now) or &quot;durationSec&quot; (1..%1), one of the two.</source>
            <translation>擱置需要 {&quot;until&quot;: 含時區偏移、晚於現在的日期時間} 或 {&quot;durationSec&quot;: 1..%1}，兩者擇一。</translation>
        </message>
        <message>
            <source>alarm %1 raised (%2 priority): %3 (value %4)</source>
            <translation>警報 %1 觸發（%2 優先度）：%3（值 %4）</translation>
        </message>
        <message>
            <source>alarm %1 returned to normal: %2 (value %3)</source>
            <translation>警報 %1 恢復正常：%2（值 %3）</translation>
        </message>
        <message>
            <source>alarm %1 %2 by %3 (comment &quot;%4&quot;)</source>
            <translation>警報 %1 由 %3 %2（備註「%4」）</translation>
        </message>
        <message>
            <source>alarm %1 %2</source>
            <translation>警報 %1 %2</translation>
        </message>
        <message>
            <source>alarm %1 %2 (id &quot;%3&quot;) refused: %4</source>
            <translation>警報 %1 %2（命令編號「%3」）被拒絕：%4</translation>
        </message>
        <message>
            <source>alarm journal failed (alarms still run, not journaled): %1</source>
            <translation>警報日誌失敗（警報仍在運作，但未記錄）：%1</translation>
        </message>
        <message>
            <source>&quot;%1&quot; is the setting of every item recorded with &quot;recordAll&quot;: give &quot;recordAll&quot;: true, or put &quot;history&quot; on the items in their watch lists.</source>
            <translation>「%1」是以 {&quot;recordAll&quot;: true} 記錄的每個項目的設定：請加上 {&quot;recordAll&quot;: true}，或在監看清單的項目上加入「history」。</translation>
        </message>
        <message>
            <source>The history store&apos;s URL holds a password: keep it in ~/.pgpass or $PGPASSWORD (the service&apos;s EnvironmentFile), out of the configuration.</source>
            <translation>歷史資料庫的 URL 含有密碼：請將密碼放在 ~/.pgpass 或 $PGPASSWORD（服務的環境設定檔），不要寫在設定檔中。</translation>
        </message>
        <message>
            <source>history store failed (values still polled and published, not recorded): %1</source>
            <translation>歷史資料庫失敗（數值仍在輪詢並發佈，但未記錄）：%1</translation>
        </message>
        <message>
            <source>history store %1 written again</source>
            <translation>歷史資料庫 %1 已恢復寫入</translation>
        </message>
        <message>
            <source>&quot;%1&quot; must name a file.</source>
            <translation>「%1」必須指定一個檔案。</translation>
        </message>
        <message>
            <source>Cannot open the alarm journal %1: %2</source>
            <translation>無法開啟警報日誌 %1：%2</translation>
        </message>
        <message>
            <source>The alarm journal %1 does not exist.</source>
            <translation>警報日誌 %1 不存在。</translation>
        </message>
        <message>
            <source>%1 is not an alarm journal (another program&apos;s SQLite database); it was left as it is.</source>
            <translation>%1 不是警報日誌（是其他程式的 SQLite 資料庫）；檔案保持原樣。</translation>
        </message>
        <message>
            <source>The alarm journal %1 has format %2, newer than this program reads (%3); it was left as it is.</source>
            <translation>警報日誌 %1 的格式為 %2，比本程式能讀取的（%3）更新；檔案保持原樣。</translation>
        </message>
        <message>
            <source>The alarm journal %1 is locked by another program (it holds a write transaction open).</source>
            <translation>警報日誌 %1 被其他程式鎖定（它保持著一個寫入交易）。</translation>
        </message>
        <message>
            <source>Cannot write to the alarm journal %1: %2</source>
            <translation>無法寫入警報日誌 %1：%2</translation>
        </message>
        <message>
            <source>Cannot read the alarm journal %1: %2</source>
            <translation>無法讀取警報日誌 %1：%2</translation>
        </message>
        <message>
            <source>The alarm journal %1, event %2: unknown %3 &quot;%4&quot;.</source>
            <translation>警報日誌 %1，事件 %2：未知的 %3「%4」。</translation>
        </message>
        <message>
            <source>The alarm journal %1, the kept state of %2: unknown %3 &quot;%4&quot;.</source>
            <translation>警報日誌 %1，%2 保存的狀態：未知的 %3「%4」。</translation>
        </message>
        <message>
            <source>Cannot open the history store %1: %2</source>
            <translation>無法開啟歷史資料庫 %1：%2</translation>
        </message>
        <message>
            <source>The history store %1 does not exist.</source>
            <translation>歷史資料庫 %1 不存在。</translation>
        </message>
        <message>
            <source>%1 is not a history store (another program&apos;s database); it was left as it is.</source>
            <translation>%1 不是歷史資料庫（是其他程式的資料庫）；檔案保持原樣。</translation>
        </message>
        <message>
            <source>The history store %1 has format %2, newer than this program reads (%3); it was left as it is.</source>
            <translation>歷史資料庫 %1 的格式為 %2，比本程式能讀取的（%3）更新；資料庫保持原樣。</translation>
        </message>
        <message>
            <source>The history store %1 is locked by another program (it holds a write transaction open).</source>
            <translation>歷史資料庫 %1 被其他程式鎖定（它保持著一個寫入交易）。</translation>
        </message>
        <message>
            <source>Cannot write to the history store %1: %2</source>
            <translation>無法寫入歷史資料庫 %1：%2</translation>
        </message>
        <message>
            <source>Cannot read the history store %1: %2</source>
            <translation>無法讀取歷史資料庫 %1：%2</translation>
        </message>
        <message>
            <source>The history store %1 has no series %2.</source>
            <translation>歷史資料庫 %1 沒有資料序列 %2。</translation>
        </message>
        <message>
            <source>Cannot open the history store %1: this build of FATEK Studio has no PostgreSQL client (use an SQLite file).</source>
            <translation>無法開啟歷史資料庫 %1：此版本的 FATEK Studio 沒有 PostgreSQL 用戶端（請改用 SQLite 檔案）。</translation>
        </message>
        <message>
            <source>The history store %1 could not be written for a while: %2 samples were lost (the oldest).</source>
            <translation>歷史資料庫 %1 有一段時間無法寫入：遺失了 %2 筆樣本（最舊的）。</translation>
        </message>
        <message>
            <source>Cannot create the history store %1: cannot create its folder %2.</source>
            <translation>無法建立歷史資料庫 %1：無法建立其資料夾 %2。</translation>
        </message>
        <message>
            <source>The history store %1 was opened to read only; nothing was written.</source>
            <translation>歷史資料庫 %1 以唯讀方式開啟；未寫入任何資料。</translation>
        </message>
        <message>
            <source>The history store %1, series %2 at %3: unknown quality %4.</source>
            <translation>歷史資料庫 %1，資料序列 %2 於 %3：未知的品質 %4。</translation>
        </message>
        <message>
            <source>%1 is not a finite number: NaN and infinities are written only to an item whose &quot;%2&quot; option is on</source>
            <translation>%1 不是有限數值：非數值與無限大只會寫入已開啟「%2」選項的項目</translation>
        </message>
        <message>
            <source>Refused: the gateway is read-only.</source>
            <translation>拒絕：閘道為唯讀。</translation>
        </message>
        <message>
            <source>Refused: %1 is not in this connection&apos;s write allowlist.</source>
            <translation>拒絕：%1 不在此連線的寫入允許清單中。</translation>
        </message>
        <message>
            <source>Refused: a retained command would write again at every restart; publish commands without the retain flag.</source>
            <translation>拒絕：保留的命令會在每次重新啟動時再次寫入；發布命令時請勿設定保留旗標。</translation>
        </message>
        <message>
            <source>Refused: a command longer than %1 bytes.</source>
            <translation>拒絕：命令超過 %1 位元組。</translation>
        </message>
        <message>
            <source>Refused: %1 writes are already waiting on this connection.</source>
            <translation>拒絕：此連線已有 %1 個寫入在等待。</translation>
        </message>
        <message>
            <source>Refused: no item &quot;%2&quot; on station &quot;%1&quot; (write the address as a watch table shows it, R100, and the station as 1 to 254).</source>
            <translation>拒絕：站號 &quot;%1&quot; 沒有項目 &quot;%2&quot;（位址請依監看表的寫法，例如 R100；站號為 1 到 254）。</translation>
        </message>
        <message>
            <source>Expired: the command is %1 s old (commands older than %2 s are not carried out); send it again.</source>
            <translation>已逾時：此命令已發出 %1 秒（超過 %2 秒的命令不予執行）；請重新傳送。</translation>
        </message>
        <message>
            <source>Expired: the command waited at the broker while the gateway was away, up to %1 s (commands older than %2 s are not carried out); send it again.</source>
            <translation>已逾時：閘道離線期間此命令在代理伺服器等候，最長 %1 秒（超過 %2 秒的命令不予執行）；請重新傳送。</translation>
        </message>
        <message>
            <source>Not carried out: the command waited at the broker while the gateway was away, for a time nobody knows; send it again, with &quot;time&quot; so that its age can be checked (at most %1 s).</source>
            <translation>未執行：閘道離線期間此命令在代理伺服器等候，等候時間無從得知；請重新傳送，並在命令中附上 {&quot;time&quot;: ...} 以便檢查其時效（最多 %1 秒）。</translation>
        </message>
        <message>
            <source>&quot;time&quot; must be a date and time in ISO 8601 with its offset (2026-11-27T10:15:00.000Z), not &quot;%1&quot;.</source>
            <translation>{&quot;time&quot;: ...} 必須是含時區偏移的日期時間（例如 2026-11-27T10:15:00.000Z），而不是 &quot;%1&quot;。</translation>
        </message>
        <message>
            <source>written</source>
            <translation>已寫入</translation>
        </message>
        <message>
            <source>Ignored a command on %1: not an item of this connection.</source>
            <translation>已忽略 %1 上的命令：不是此連線的項目。</translation>
        </message>
        <message>
            <source>write station %1 %2 = &quot;%3&quot; (id &quot;%4&quot;): %5</source>
            <translation>寫入站號 %1 %2 = &quot;%3&quot;（命令 ID &quot;%4&quot;）：%5</translation>
        </message>
        <message>
            <source>PLC link %1: %2</source>
            <translation>PLC 連線%1：%2</translation>
        </message>
        <message>
            <source>PLC link %1</source>
            <translation>PLC 連線%1</translation>
        </message>
        <message>
            <source>broker %1 connected</source>
            <translation>已連線到代理伺服器 %1</translation>
        </message>
        <message>
            <source>broker down: %1</source>
            <translation>代理伺服器中斷：%1</translation>
        </message>
        <message>
            <source>started: %1 {1:item|items} from %2, broker %3</source>
            <translation>已啟動：%1 個項目，來自 %2，代理伺服器 %3</translation>
        </message>
        <message>
            <source>stopped (status offline)</source>
            <translation>已停止（狀態為離線）</translation>
        </message>
        <message>
            <source>reloading %1: changed connections restart, the others keep running</source>
            <translation>重新載入 %1：變更的連線重新啟動，其餘繼續執行</translation>
        </message>
        <message>
            <source>not reloaded, the running configuration stays: %1: %2</source>
            <translation>未重新載入，維持執行中的設定：%1：%2</translation>
        </message>
        <message>
            <source>reloaded</source>
            <translation>已重新載入</translation>
        </message>
        <message>
            <source>Passed with remark</source>
            <translation>合格（附註）</translation>
        </message>
        <message>
            <source>Deferred</source>
            <translation>延後</translation>
        </message>
        <message>
            <source>Not applicable</source>
            <translation>不適用</translation>
        </message>
        <message>
            <source>%1 %: %2</source>
            <translation>%1 %：%2</translation>
        </message>
        <message>
            <source>%1 %: found %2, left %3</source>
            <translation>%1 %：調整前 %2，調整後 %3</translation>
        </message>
        <message>
            <source>%1 %: %2, expected %3</source>
            <translation>%1 %：%2，預期 %3</translation>
        </message>
        <message>
            <source>%1 (tolerance %2)</source>
            <translation>%1（容許誤差 %2）</translation>
        </message>
        <message>
            <source>%1 has no expected values: give its scale (raw and engineering low and high) in the plan before it can pass</source>
            <translation>%1 沒有預期值：請先在計畫中設定其刻度（原始值與工程值的下限和上限），才能判定合格</translation>
        </message>
        <message>
            <source>The checkout is not running: start it first. Nothing was forced.</source>
            <translation>點檢尚未開始：請先開始。沒有強制任何輸出。</translation>
        </message>
        <message>
            <source>%1 is not a point of the checkout</source>
            <translation>%1 不是此次點檢的點</translation>
        </message>
        <message>
            <source>%1 is not an analog point</source>
            <translation>%1 不是類比點</translation>
        </message>
        <message>
            <source>%1: &quot;passed with remark&quot; needs the remark</source>
            <translation>%1：「合格（附註）」需要填寫附註</translation>
        </message>
        <message>
            <source>%1: &quot;deferred&quot; needs the reason</source>
            <translation>%1：「延後」需要填寫原因</translation>
        </message>
        <message>
            <source>%1 cannot pass clean: %2 changed while it was tested (crossed wiring?). Re-test it, or pass it with a remark.</source>
            <translation>%1 不能直接判定合格：測試時 %2 也變化了（配線交錯？）。請重新測試，或以附註判定合格。</translation>
        </message>
        <message>
            <source>%1 passes or fails by what is read: read it at each check</source>
            <translation>%1 依讀取值判定合格與否：請在每個檢查點讀取</translation>
        </message>
        <message>
            <source>%1 has no check at %2 %</source>
            <translation>%1 沒有 %2 % 的檢查點</translation>
        </message>
        <message>
            <source>%1 at %2 %: read the value as found before the value as left</source>
            <translation>%1 在 %2 %：請先讀取調整前的值，再讀取調整後的值</translation>
        </message>
        <message>
            <source>%1 still fails: re-test it before its punch item is closed out</source>
            <translation>%1 仍不合格：請先重新測試，再將其待辦事項結案</translation>
        </message>
        <message>
            <source>%1 is not on the punch list</source>
            <translation>%1 不在待辦清單上</translation>
        </message>
        <message>
            <source>The PLC refuses %1 (%2): %3 {3:point|points} to take out of the plan. Nothing was forced.</source>
            <translation>PLC 拒絕 %1（%2）：請將這 %3 個點自計畫中移除。沒有強制任何輸出。</translation>
        </message>
        <message>
            <source>%1 are read again</source>
            <translation>%1 已恢復讀取</translation>
        </message>
        <message>
            <source>checks &quot;%1&quot;: per cents from 0 to 100 separated by &quot;/&quot;</source>
            <translation>檢查點「%1」：應為 0 到 100 的百分比，以「/」分隔</translation>
        </message>
        <message>
            <source>checkout file version %1 is not supported (this program reads 1 to %2)</source>
            <translation>不支援點檢檔版本 %1（本程式可讀取 1 到 %2）</translation>
        </message>
        <message>
            <source>info</source>
            <translation>資訊</translation>
        </message>
        <message>
            <source>point %1 (%2)</source>
            <translation>第 %1 點（%2）</translation>
        </message>
        <message>
            <source>earlier attempt %1</source>
            <translation>第 %1 次先前測試</translation>
        </message>
        <message>
            <source>reading %1</source>
            <translation>第 %1 筆讀值</translation>
        </message>
        <message>
            <source>scale</source>
            <translation>刻度</translation>
        </message>
        <message>
            <source>punch</source>
            <translation>待辦</translation>
        </message>
        <message>
            <source>&quot;%1&quot; cannot be &quot;%2&quot;</source>
            <translation>「%1」不能是「%2」</translation>
        </message>
        <message>
            <source>%1 {1:point|points}: %2 passed, %3 passed with remark, %4 failed, %5 deferred, %6 not applicable, %7 untested.</source>
            <translation>共 %1 點：%2 點合格，%3 點合格（附註），%4 點不合格，%5 點延後，%6 點不適用，%7 點未測試。</translation>
        </message>
        <message>
            <source>Punch list</source>
            <translation>待辦清單</translation>
        </message>
        <message>
            <source>The punch list is empty: no point failed or was deferred.</source>
            <translation>待辦清單是空的：沒有不合格或延後的點。</translation>
        </message>
        <message>
            <source>Attempts</source>
            <translation>次數</translation>
        </message>
        <message>
            <source>Owner</source>
            <translation>負責人</translation>
        </message>
        <message>
            <source>State</source>
            <translation>狀態</translation>
        </message>
        <message>
            <source>open</source>
            <translation>未結案</translation>
        </message>
        <message>
            <source>closed %1 by %2</source>
            <translation>%1 由 %2 結案</translation>
        </message>
        <message>
            <source>Document</source>
            <translation>文件編號</translation>
        </message>
        <message>
            <source>Revision</source>
            <translation>版次</translation>
        </message>
        <message>
            <source>Name the engineer who records the results: the report says who tested each point.</source>
            <translation>請填寫記錄結果的工程師：報告會載明每一點由誰測試。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendHistory</name>
        <message numerus="yes">
            <source>%n value(s) exported to %1.</source>
            <translation>
                <numerusform>已將 %n 個數值匯出到 %1。</numerusform>
            </translation>
        </message>
        <message>
            <source>History: %1</source>
            <translation>歷史資料：%1</translation>
        </message>
        <message>
            <source>Export Range to CSV</source>
            <translation>將範圍匯出為 CSV</translation>
        </message>
        <message>
            <source>None of the trend&apos;s items is recorded in the history.</source>
            <translation>趨勢圖中沒有任何項目記錄在歷史資料中。</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>無法寫入 %1：%2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendNavigation</name>
        <message>
            <source>How much time the trend shows</source>
            <translation>趨勢圖顯示的時間長度</translation>
        </message>
        <message>
            <source>10 s</source>
            <translation>10 秒</translation>
        </message>
        <message>
            <source>1 min</source>
            <translation>1 分鐘</translation>
        </message>
        <message>
            <source>10 min</source>
            <translation>10 分鐘</translation>
        </message>
        <message>
            <source>1 h</source>
            <translation>1 小時</translation>
        </message>
        <message>
            <source>8 h</source>
            <translation>8 小時</translation>
        </message>
        <message>
            <source>24 h</source>
            <translation>24 小時</translation>
        </message>
        <message>
            <source>7 days</source>
            <translation>7 天</translation>
        </message>
        <message>
            <source>Custom…</source>
            <translation>自訂…</translation>
        </message>
        <message>
            <source>Scroll back in time (Shift+wheel over the chart too); Reset Zoom follows the present again</source>
            <translation>向前捲動時間（也可在圖上按住 Shift 並轉動滾輪）；「重設縮放」會再次跟隨目前時間</translation>
        </message>
        <message>
            <source>Custom Time Range</source>
            <translation>自訂時間範圍</translation>
        </message>
        <message>
            <source>&amp;From:</source>
            <translation>起(&amp;F)：</translation>
        </message>
        <message>
            <source>&amp;To:</source>
            <translation>迄(&amp;T)：</translation>
        </message>
        <message>
            <source>The end must come after the beginning.</source>
            <translation>結束時間必須晚於開始時間。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::UiText</name>
        <message>
            <source>bit</source>
            <translation>位元</translation>
        </message>
        <message>
            <source>unsigned</source>
            <translation>無號整數</translation>
        </message>
        <message>
            <source>signed</source>
            <translation>有號整數</translation>
        </message>
        <message>
            <source>hex</source>
            <translation>十六進位</translation>
        </message>
        <message>
            <source>binary</source>
            <translation>二進位</translation>
        </message>
        <message>
            <source>BCD</source>
            <translation>BCD</translation>
        </message>
        <message>
            <source>float</source>
            <translation>浮點數</translation>
        </message>
        <message>
            <source>ASCII</source>
            <translation>ASCII</translation>
        </message>
        <message>
            <source>double</source>
            <translation>倍精度浮點數</translation>
        </message>
        <message>
            <source>input</source>
            <translation>輸入點</translation>
        </message>
        <message>
            <source>output relay</source>
            <translation>輸出繼電器</translation>
        </message>
        <message>
            <source>internal relay</source>
            <translation>內部繼電器</translation>
        </message>
        <message>
            <source>step relay</source>
            <translation>步進繼電器</translation>
        </message>
        <message>
            <source>timer contact</source>
            <translation>計時器接點</translation>
        </message>
        <message>
            <source>counter contact</source>
            <translation>計數器接點</translation>
        </message>
        <message>
            <source>inputs as 16-bit word</source>
            <translation>輸入點（16 位元字組）</translation>
        </message>
        <message>
            <source>outputs as 16-bit word</source>
            <translation>輸出點（16 位元字組）</translation>
        </message>
        <message>
            <source>internal relays as 16-bit word</source>
            <translation>內部繼電器（16 位元字組）</translation>
        </message>
        <message>
            <source>step relays as 16-bit word</source>
            <translation>步進繼電器（16 位元字組）</translation>
        </message>
        <message>
            <source>timer contacts as 16-bit word</source>
            <translation>計時器接點（16 位元字組）</translation>
        </message>
        <message>
            <source>counter contacts as 16-bit word</source>
            <translation>計數器接點（16 位元字組）</translation>
        </message>
        <message>
            <source>timer register</source>
            <translation>計時器暫存器</translation>
        </message>
        <message>
            <source>counter register</source>
            <translation>計數器暫存器</translation>
        </message>
        <message>
            <source>data register</source>
            <translation>資料暫存器</translation>
        </message>
        <message>
            <source>file register</source>
            <translation>檔案暫存器</translation>
        </message>
        <message>
            <source>inputs as 32-bit word</source>
            <translation>輸入點（32 位元雙字組）</translation>
        </message>
        <message>
            <source>outputs as 32-bit word</source>
            <translation>輸出點（32 位元雙字組）</translation>
        </message>
        <message>
            <source>internal relays as 32-bit word</source>
            <translation>內部繼電器（32 位元雙字組）</translation>
        </message>
        <message>
            <source>step relays as 32-bit word</source>
            <translation>步進繼電器（32 位元雙字組）</translation>
        </message>
        <message>
            <source>timer contacts as 32-bit word</source>
            <translation>計時器接點（32 位元雙字組）</translation>
        </message>
        <message>
            <source>counter contacts as 32-bit word</source>
            <translation>計數器接點（32 位元雙字組）</translation>
        </message>
        <message>
            <source>timer register pair</source>
            <translation>計時器暫存器對</translation>
        </message>
        <message>
            <source>counter register pair</source>
            <translation>計數器暫存器對</translation>
        </message>
        <message>
            <source>data register pair</source>
            <translation>資料暫存器對</translation>
        </message>
        <message>
            <source>file register pair</source>
            <translation>檔案暫存器對</translation>
        </message>
        <message>
            <source>auto-detect</source>
            <translation>自動偵測</translation>
        </message>
        <message>
            <source>%1, %2</source>
            <extracomment>Link settings: medium (TCP 10.0.0.5:500, COM3 9600 7E1) and protocol.</extracomment>
            <translation>%1，%2</translation>
        </message>
        <message>
            <source>(no port)</source>
            <translation>（無連接埠）</translation>
        </message>
        <message>
            <source>OS %1</source>
            <translation>OS %1</translation>
        </message>
        <message>
            <source>program %1 words</source>
            <translation>程式 %1 字組</translation>
        </message>
        <message>
            <source>%1 I/O points</source>
            <translation>%1 個 I/O 點</translation>
        </message>
        <message>
            <source>main unit type %1</source>
            <translation>主機類型 %1</translation>
        </message>
        <message>
            <source>M series</source>
            <translation>M 系列</translation>
        </message>
        <message>
            <source>, </source>
            <comment>between the parts of a model text</comment>
            <translation>，</translation>
        </message>
    </context>
    <context>
        <name>Fatek::SavedConnection</name>
        <message>
            <source>MQTT gateway %1 on %2 (prefix %3)</source>
            <translation>MQTT 閘道器 %1，位於 %2（前綴 %3）</translation>
        </message>
    </context>
    <context>
        <name>Fatek::DemoSimulator</name>
        <message>
            <source>Demo</source>
            <translation>示範</translation>
        </message>
        <message>
            <source>Scan counter</source>
            <translation>掃描計數</translation>
        </message>
        <message>
            <source>counts ladder scans</source>
            <translation>計算階梯圖掃描次數</translation>
        </message>
        <message>
            <source>Sine</source>
            <translation>正弦波</translation>
        </message>
        <message>
            <source>±1000, 10 s period</source>
            <translation>±1000，週期 10 秒</translation>
        </message>
        <message>
            <source>Blink</source>
            <translation>閃爍</translation>
        </message>
        <message>
            <source>1 Hz</source>
            <translation>1 Hz</translation>
        </message>
        <message>
            <source>Walking bit %1</source>
            <translation>跑馬燈位元 %1</translation>
        </message>
        <message>
            <source>one step per 250 ms</source>
            <translation>每 250 ms 移動一步</translation>
        </message>
        <message>
            <source>Ramp</source>
            <translation>斜坡</translation>
        </message>
        <message>
            <source>0..99999, one step per 10 ms</source>
            <translation>0..99999，每 10 ms 加一</translation>
        </message>
    </context>
    <context>
        <name>Fatek::DiscreteControlBatch</name>
        <message>
            <source>Disable</source>
            <translation>停用</translation>
        </message>
        <message>
            <source>Enable</source>
            <translation>啟用</translation>
        </message>
        <message>
            <source>Set ON</source>
            <translation>設為 ON</translation>
        </message>
        <message>
            <source>Reset OFF</source>
            <translation>復歸 OFF</translation>
        </message>
        <message>
            <source>Disabled</source>
            <translation>已停用</translation>
        </message>
        <message>
            <source>Enabled</source>
            <translation>已啟用</translation>
        </message>
        <message>
            <source>Set ON</source>
            <comment>past</comment>
            <extracomment>Past tense, as in "Set ON 3 points."</extracomment>
            <translation>已設為 ON</translation>
        </message>
        <message>
            <source>Reset OFF</source>
            <comment>past</comment>
            <extracomment>Past tense, as in "Reset OFF 3 points."</extracomment>
            <translation>已復歸 OFF</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>%1: %2 done, %3 failed — %4</source>
            <translation>%1：完成 %2 個，失敗 %3 個 — %4</translation>
        </message>
        <message>
            <source> (and %1 more)</source>
            <translation>（另有 %1 個）</translation>
        </message>
        <message numerus="yes">
            <source>%1 %n points (%2, %3 … %4)</source>
            <extracomment>%1 is the action (Disable, Set ON...), %2..%4 the first, second and last point.</extracomment>
            <translation>
                <numerusform>%1 %n 個點（%2、%3 … %4）</numerusform>
            </translation>
        </message>
        <message>
            <source>%1 1 point.</source>
            <extracomment>%1 is the past action (Disabled, Enabled, Set ON, Reset OFF).</extracomment>
            <translation>%1 1 個點。</translation>
        </message>
        <message>
            <source>%1 %2 points.</source>
            <translation>%1 %2 個點。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::DiscreteScan</name>
        <message>
            <source>“%1” is not a discrete type; use X, Y, M, S, T or C.</source>
            <translation>「%1」不是離散點類型；請使用 X、Y、M、S、T 或 C。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::DiscreteTableModel</name>
        <message>
            <source>ON</source>
            <translation>導通</translation>
        </message>
        <message>
            <source>OFF</source>
            <translation>斷開</translation>
        </message>
        <message>
            <source>disabled (forced)</source>
            <translation>已停用（強制中）</translation>
        </message>
        <message>
            <source>enabled</source>
            <translation>已啟用</translation>
        </message>
        <message>
            <source>Point</source>
            <translation>點</translation>
        </message>
        <message>
            <source>State</source>
            <translation>狀態</translation>
        </message>
        <message>
            <source>Forcing</source>
            <translation>強制</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>名稱</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ForcedPointsView</name>
        <message>
            <source>Ranges:</source>
            <translation>範圍：</translation>
        </message>
        <message>
            <source>Scan</source>
            <translation>掃描</translation>
        </message>
        <message>
            <source>Enable all</source>
            <translation>全部啟用</translation>
        </message>
        <message>
            <source>Give every listed point back to the ladder</source>
            <translation>將列出的每一點交還給階梯圖控制</translation>
        </message>
        <message>
            <source>Press Scan to list the forced points.</source>
            <translation>按「掃描」列出強制中的點。</translation>
        </message>
        <message>
            <source>No connection.</source>
            <translation>沒有連線。</translation>
        </message>
        <message>
            <source>Read-only (operator) mode: forcing is disabled.</source>
            <translation>唯讀（操作員）模式：已停用強制功能。</translation>
        </message>
        <message>
            <source>Scanning %1 …</source>
            <translation>正在掃描 %1 …</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>Scan incomplete — %1</source>
            <translation>掃描未完成 — %1</translation>
        </message>
        <message>
            <source>%1 on %2?</source>
            <translation>要對 %2 執行「%1」嗎？</translation>
        </message>
        <message>
            <source>Enable all forced points</source>
            <translation>啟用所有強制中的點</translation>
        </message>
        <message>
            <source>Enable all cancelled; the points stay forced.</source>
            <translation>已取消全部啟用；這些點仍維持強制。</translation>
        </message>
        <message>
            <source>All points of the PLC</source>
            <translation>PLC 的所有點</translation>
        </message>
        <message>
            <source>Empty: every X Y M S T C point the PLC reports in its status. Or type ranges to scan, e.g. X0-255, Y0-255, M0-999</source>
            <translation>留空：掃描 PLC 在其狀態中回報的每個 X Y M S T C 點。或輸入要掃描的範圍，例如 X0-255, Y0-255, M0-999</translation>
        </message>
        <message>
            <source>Reading the PLC's sizes …</source>
            <translation>正在讀取 PLC 的點數 …</translation>
        </message>
        <message>
            <source>The PLC did not report its sizes (%1): default ranges scanned.</source>
            <translation>PLC 沒有回報點數（%1）：已掃描預設範圍。</translation>
        </message>
        <message>
            <source>The PLC did not report how many %1 it has: default ranges scanned for them.</source>
            <translation>PLC 沒有回報 %1 的點數：這些已掃描預設範圍。</translation>
        </message>
        <message>
            <source>Scanned %1: no forced points.</source>
            <translation>已掃描 %1：沒有強制中的點。</translation>
        </message>
        <message>
            <source>Scanned %1: 1 forced point; enable it before leaving the site.</source>
            <translation>已掃描 %1：有 1 個強制中的點；離開現場前請將它啟用。</translation>
        </message>
        <message>
            <source>Scanned %1: %2 forced points; enable them before leaving the site.</source>
            <translation>已掃描 %1：有 %2 個強制中的點；離開現場前請將它們啟用。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ForcingPanel</name>
        <message>
            <source>Show</source>
            <translation>顯示</translation>
        </message>
        <message>
            <source>Refresh every second</source>
            <translation>每秒重新整理</translation>
        </message>
        <message>
            <source>Type:</source>
            <translation>類型：</translation>
        </message>
        <message>
            <source>From:</source>
            <translation>起始：</translation>
        </message>
        <message>
            <source>Points:</source>
            <translation>點數：</translation>
        </message>
        <message>
            <source>Disable (force)</source>
            <translation>停用（強制）</translation>
        </message>
        <message>
            <source>Enable</source>
            <translation>啟用</translation>
        </message>
        <message>
            <source>Set ON</source>
            <translation>設為 ON</translation>
        </message>
        <message>
            <source>Reset OFF</source>
            <translation>復歸 OFF</translation>
        </message>
        <message>
            <source>Discretes</source>
            <translation>離散點</translation>
        </message>
        <message>
            <source>Forced points</source>
            <translation>強制中的點</translation>
        </message>
        <message>
            <source>No connection: choose a connection and a station.</source>
            <translation>沒有連線：請選擇連線與站號。</translation>
        </message>
        <message>
            <source>Station %1 on “%2”</source>
            <translation>「%2」上的站號 %1</translation>
        </message>
        <message>
            <source>Only X, Y, M, S, T and C points can be forced.</source>
            <translation>只有 X、Y、M、S、T 和 C 點可以強制。</translation>
        </message>
        <message>
            <source>Could not read: %1</source>
            <translation>無法讀取：%1</translation>
        </message>
        <message>
            <source>Select the points first (Ctrl/Shift-click for several).</source>
            <translation>請先選取點（按住 Ctrl 或 Shift 點選可選取多個）。</translation>
        </message>
        <message>
            <source>%1 on %2?</source>
            <translation>要對 %2 執行「%1」嗎？</translation>
        </message>
        <message>
            <source>Forcing</source>
            <translation>強制</translation>
        </message>
        <message>
            <source>Cancelled: nothing sent.</source>
            <translation>已取消：未送出任何資料。</translation>
        </message>
        <message>
            <source>%1 …</source>
            <translation>%1 …</translation>
        </message>
        <message>
            <source>Read-only (operator) mode: forcing is disabled.</source>
            <translation>唯讀（操作員）模式：已停用強制功能。</translation>
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
            <translation>語言(&amp;L)</translation>
        </message>
        <message>
            <source>System</source>
            <translation>系統預設</translation>
        </message>
        <message>
            <source>Language</source>
            <translation>語言</translation>
        </message>
        <message>
            <source>The new language applies when FATEK Studio is started again.</source>
            <translation>新的語言會在下次啟動 FATEK Studio 時套用。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::LinkStatusLabel</name>
        <message>
            <source>No connection</source>
            <translation>沒有連線</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message numerus="yes">
            <source> · %n failed attempt(s)</source>
            <translation>
                <numerusform> · 失敗 %n 次</numerusform>
            </translation>
        </message>
        <message>
            <source> · F5 reconnects now</source>
            <translation> · 按 F5 立即重新連線</translation>
        </message>
        <message>
            <source>%1: %2 · %3 req/s · %4 errors · RTT %5</source>
            <translation>%1：%2 · %3 次請求/秒 · %4 個錯誤 · RTT %5</translation>
        </message>
        <message>
            <source>%1 ms</source>
            <translation>%1 ms</translation>
        </message>
        <message>
            <source>%1: %2 · through the MQTT gateway</source>
            <translation>%1：%2 · 透過 MQTT 閘道器</translation>
        </message>
    </context>
    <context>
        <name>Fatek::LoopbackDialog</name>
        <message>
            <source>Loopback test</source>
            <translation>迴路測試</translation>
        </message>
        <message>
            <source>Text</source>
            <translation>文字</translation>
        </message>
        <message>
            <source>Hex bytes</source>
            <translation>十六進位位元組</translation>
        </message>
        <message>
            <source>Generated pattern</source>
            <translation>自動產生的樣式</translation>
        </message>
        <message>
            <source> bytes</source>
            <translation> 位元組</translation>
        </message>
        <message>
            <source>Test data:</source>
            <translation>測試資料：</translation>
        </message>
        <message>
            <source>Repeat:</source>
            <translation>重複次數：</translation>
        </message>
        <message>
            <source> ms</source>
            <translation> ms</translation>
        </message>
        <message>
            <source>Interval:</source>
            <translation>間隔：</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>開始</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>停止</translation>
        </message>
        <message>
            <source>Stopped: the target changed.</source>
            <translation>已停止：目標已變更。</translation>
        </message>
        <message>
            <source>Running %1 loopback tests of %2 bytes …</source>
            <translation>正在執行 %1 次 %2 位元組的迴路測試 …</translation>
        </message>
        <message>
            <source>Stopped after %1 runs.</source>
            <translation>執行 %1 次後停止。</translation>
        </message>
        <message>
            <source>%1  OK        %2 ms</source>
            <translation>%1  正常      %2 ms</translation>
        </message>
        <message>
            <source>%1  MISMATCH  %2 ms: got %3</source>
            <translation>%1  不符      %2 ms：收到 %3</translation>
        </message>
        <message>
            <source>%1  TIMEOUT   %2</source>
            <translation>%1  逾時      %2</translation>
        </message>
        <message>
            <source>%1  ERROR     %2</source>
            <translation>%1  錯誤      %2</translation>
        </message>
        <message>
            <source>Done.</source>
            <translation>完成。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::LoopbackStats</name>
        <message>
            <source>%1 runs: %2 OK, %3 mismatch, %4 timeout, %5 other errors</source>
            <translation>執行 %1 次：正常 %2，不符 %3，逾時 %4，其他錯誤 %5</translation>
        </message>
        <message>
            <source> — round trip min %1 / mean %2 / max %3 / p99 %4 ms</source>
            <translation> — 往返時間 最小 %1 / 平均 %2 / 最大 %3 / p99 %4 ms</translation>
        </message>
    </context>
    <context>
        <name>Fatek::MainWindow</name>
        <message numerus="yes">
            <source>Closing %1: sending %n queued write(s) first (at most %2 s)…</source>
            <translation>
                <numerusform>正在關閉 %1：先送出 %n 筆排隊中的寫入（最多 %2 秒）…</numerusform>
            </translation>
        </message>
        <message>
            <source>Connections</source>
            <translation>連線</translation>
        </message>
        <message>
            <source>Operator mode (read-only)</source>
            <translation>操作員模式（唯讀）</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>%1: %2 (%3)</source>
            <translation>%1：%2（%3）</translation>
        </message>
        <message>
            <source>&amp;File</source>
            <translation>檔案(&amp;F)</translation>
        </message>
        <message>
            <source>Main</source>
            <translation>主工具列</translation>
        </message>
        <message>
            <source>&amp;New Connection…</source>
            <translation>新增連線(&amp;N)…</translation>
        </message>
        <message>
            <source>&amp;Recent Connections</source>
            <translation>最近的連線(&amp;R)</translation>
        </message>
        <message>
            <source>&amp;Close Connection</source>
            <translation>關閉連線(&amp;C)</translation>
        </message>
        <message>
            <source>New &amp;Watch Table</source>
            <translation>新增監看表(&amp;W)</translation>
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation>結束(&amp;Q)</translation>
        </message>
        <message>
            <source>&amp;Watch</source>
            <translation>監看(&amp;W)</translation>
        </message>
        <message>
            <source>&amp;Add Items…</source>
            <translation>加入項目(&amp;A)…</translation>
        </message>
        <message>
            <source>&amp;Pause Table</source>
            <translation>暫停監看表(&amp;P)</translation>
        </message>
        <message>
            <source>&amp;Close Table</source>
            <translation>關閉監看表(&amp;C)</translation>
        </message>
        <message>
            <source>&amp;View</source>
            <translation>檢視(&amp;V)</translation>
        </message>
        <message>
            <source>&amp;Tools</source>
            <translation>工具(&amp;T)</translation>
        </message>
        <message>
            <source>Connecting to %1 (%2)…</source>
            <translation>正在連線到 %1（%2）…</translation>
        </message>
        <message>
            <source>Watch %1</source>
            <translation>監看表 %1</translation>
        </message>
        <message>
            <source>Rename Watch Table</source>
            <translation>重新命名監看表</translation>
        </message>
        <message>
            <source>Name:</source>
            <translation>名稱：</translation>
        </message>
        <message>
            <source>The demo simulator could not start: %1</source>
            <translation>無法啟動示範模擬器：%1</translation>
        </message>
        <message>
            <source>Demo PLC</source>
            <translation>示範 PLC</translation>
        </message>
        <message>
            <source>Starting the demo simulator…</source>
            <translation>正在啟動示範模擬器…</translation>
        </message>
        <message numerus="yes">
            <source>%n saved connection(s) could not be read (kept unchanged)</source>
            <translation>
                <numerusform>%n 個已儲存的連線無法讀取（保持原樣）</numerusform>
            </translation>
        </message>
        <message>
            <source>Reconn&amp;ect Now</source>
            <translation>立即重新連線(&amp;E)</translation>
        </message>
        <message>
            <source>Reconnecting %1 now…</source>
            <translation>正在立即重新連線 %1…</translation>
        </message>
        <message>
            <source>Try the current connection again at once instead of waiting for the next attempt</source>
            <translation>立即重試目前的連線，不等待下一次嘗試</translation>
        </message>
        <message>
            <source>%1 — %2, station %3</source>
            <translation>%1 — %2，站號 %3</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ClosedTables</name>
        <message>
            <source>&amp;Reopen Closed Table</source>
            <translation>重新開啟已關閉的監看表(&amp;R)</translation>
        </message>
        <message numerus="yes">
            <source>Closed “%1” (%n row(s)): %2 reopens it.</source>
            <translation>
                <numerusform>已關閉「%1」（%n 列）：按 %2 可重新開啟。</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Reopened “%1” (%n row(s)).</source>
            <translation>
                <numerusform>已重新開啟「%1」（%n 列）。</numerusform>
            </translation>
        </message>
        <message>
            <source>No watch table was closed</source>
            <translation>沒有已關閉的監看表</translation>
        </message>
        <message>
            <source>Open “%1” again, with its rows and settings</source>
            <translation>重新開啟「%1」，連同其列與設定</translation>
        </message>
    </context>
    <context>
        <name>Fatek::HelpMenu</name>
        <message>
            <source>&amp;Help</source>
            <translation>說明(&amp;H)</translation>
        </message>
        <message>
            <source>&amp;User Guide</source>
            <translation>使用手冊(&amp;U)</translation>
        </message>
        <message>
            <source>&amp;Keyboard Shortcuts</source>
            <translation>鍵盤快速鍵(&amp;K)</translation>
        </message>
        <message>
            <source>&amp;About FATEK Studio</source>
            <translation>關於 FATEK Studio(&amp;A)</translation>
        </message>
        <message>
            <source>About FATEK Studio</source>
            <translation>關於 FATEK Studio</translation>
        </message>
        <message>
            <source>FATEK Studio %1
Commissioning and monitoring tool for FATEK PLCs.</source>
            <translation>FATEK Studio %1
永宏 FATEK PLC 的試車與監控工具。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ShortcutListDialog</name>
        <message>
            <source>Watch table</source>
            <translation>監看表</translation>
        </message>
        <message>
            <source>Main window</source>
            <translation>主視窗</translation>
        </message>
        <message>
            <source>Keyboard Shortcuts</source>
            <translation>鍵盤快速鍵</translation>
        </message>
        <message>
            <source>Keys</source>
            <translation>按鍵</translation>
        </message>
        <message>
            <source>Action</source>
            <translation>動作</translation>
        </message>
        <message>
            <source>Where</source>
            <translation>位置</translation>
        </message>
    </context>
    <context>
        <name>Fatek::UserGuideDialog</name>
        <message>
            <source>FATEK Studio User Guide</source>
            <translation>FATEK Studio 使用手冊</translation>
        </message>
        <message>
            <source>Back</source>
            <translation>上一頁</translation>
        </message>
        <message>
            <source>Forward</source>
            <translation>下一頁</translation>
        </message>
        <message>
            <source>Contents</source>
            <translation>目錄</translation>
        </message>
        <message>
            <source>%1 is not part of the user guide built into the program.</source>
            <translation>%1 不在程式內建的使用手冊中。</translation>
        </message>
        <message>
            <source>FATEK Studio User Guide — %1</source>
            <translation>FATEK Studio 使用手冊 — %1</translation>
        </message>
    </context>
    <context>
        <name>Fatek::QuitQuestions</name>
        <message>
            <source>The watch list %1 has changes that are not saved.</source>
            <translation>監看清單 %1 有尚未儲存的變更。</translation>
        </message>
        <message>
            <source>(untitled)</source>
            <translation>（未命名）</translation>
        </message>
        <message>
            <source>Data logging to %1 is running; quitting stops it.</source>
            <translation>正在記錄資料到 %1；結束程式會停止記錄。</translation>
        </message>
        <message>
            <source>Quit FATEK Studio</source>
            <translation>結束 FATEK Studio</translation>
        </message>
        <message>
            <source>&amp;Save and Quit</source>
            <translation>儲存並結束(&amp;S)</translation>
        </message>
        <message>
            <source>Quit &amp;Without Saving</source>
            <translation>不儲存直接結束(&amp;W)</translation>
        </message>
        <message>
            <source>Stop Logging and &amp;Quit</source>
            <translation>停止記錄並結束(&amp;Q)</translation>
        </message>
        <message>
            <source>Writes not sent yet</source>
            <translation>尚有寫入未送出</translation>
        </message>
        <message numerus="yes">
            <source>%n write(s) to the PLC have not been sent yet.</source>
            <translation>
                <numerusform>尚有 %n 筆寫入未送到 PLC。</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Wait for them (at most %n second(s)), or drop them? Dropped writes never reach the PLC.</source>
            <translation>
                <numerusform>要等候送出（最多 %n 秒），還是捨棄？捨棄的寫入不會送到 PLC。</numerusform>
            </translation>
        </message>
        <message>
            <source>&amp;Wait and Quit</source>
            <translation>等候後結束(&amp;W)</translation>
        </message>
        <message>
            <source>&amp;Drop and Quit</source>
            <translation>捨棄並結束(&amp;D)</translation>
        </message>
        <message numerus="yes">
            <source>Sending %n queued write(s) before quitting (at most %1 s)…</source>
            <translation>
                <numerusform>結束前正在送出 %n 筆排隊中的寫入（最多 %1 秒）…</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>Fatek::OperatorMode</name>
        <message>
            <source>&amp;Operator Mode (Read-Only)</source>
            <translation>操作員模式（唯讀）(&amp;O)</translation>
        </message>
        <message>
            <source>Operator Mode Pass&amp;word…</source>
            <translation>操作員模式密碼(&amp;W)…</translation>
        </message>
        <message>
            <source>Started with --read-only: operator mode stays on until the program is restarted without it.</source>
            <translation>以 --read-only 啟動：在不帶此選項重新啟動程式之前，操作員模式會保持開啟。</translation>
        </message>
        <message>
            <source>Operator-mode password:</source>
            <translation>操作員模式密碼：</translation>
        </message>
        <message>
            <source>Wrong operator-mode password: operator mode stays on.</source>
            <translation>操作員模式密碼錯誤：操作員模式保持開啟。</translation>
        </message>
        <message>
            <source>Leave operator mode? Writes, forcing, RUN/STOP and raw frames will reach the PLC again.</source>
            <translation>要離開操作員模式嗎？寫入、強制、RUN/STOP 與原始訊框將再次送達 PLC。</translation>
        </message>
        <message>
            <source>Operator mode on: the PLC is read-only.</source>
            <translation>操作員模式已開啟：PLC 為唯讀。</translation>
        </message>
        <message>
            <source>Operator mode off.</source>
            <translation>操作員模式已關閉。</translation>
        </message>
        <message>
            <source>Operator Mode</source>
            <translation>操作員模式</translation>
        </message>
        <message>
            <source>New operator-mode password (empty: none):</source>
            <translation>新的操作員模式密碼（空白表示不設密碼）：</translation>
        </message>
        <message>
            <source>Repeat the password:</source>
            <translation>再次輸入密碼：</translation>
        </message>
        <message>
            <source>The passwords differ: nothing changed.</source>
            <translation>兩次輸入的密碼不同：未做任何變更。</translation>
        </message>
        <message>
            <source>Operator-mode password removed.</source>
            <translation>已移除操作員模式密碼。</translation>
        </message>
        <message>
            <source>Operator-mode password set.</source>
            <translation>已設定操作員模式密碼。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::PlcControlPanel</name>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>PLC status</source>
            <translation>PLC 狀態</translation>
        </message>
        <message>
            <source>RUN</source>
            <translation>執行</translation>
        </message>
        <message>
            <source>Battery low</source>
            <translation>電池電量低</translation>
        </message>
        <message>
            <source>Ladder checksum error</source>
            <translation>階梯圖檢查碼錯誤</translation>
        </message>
        <message>
            <source>Memory card / ROM pack</source>
            <translation>記憶卡 / ROM 卡匣</translation>
        </message>
        <message>
            <source>Watchdog error</source>
            <translation>看門狗錯誤</translation>
        </message>
        <message>
            <source>ID set</source>
            <translation>已設定 ID</translation>
        </message>
        <message>
            <source>Emergency stop</source>
            <translation>緊急停止</translation>
        </message>
        <message>
            <source>STOP</source>
            <translation>停止</translation>
        </message>
        <message>
            <source>Refresh</source>
            <translation>重新整理</translation>
        </message>
        <message>
            <source>Detail status (53)</source>
            <translation>詳細狀態 (53)</translation>
        </message>
        <message>
            <source>Model:</source>
            <translation>機型：</translation>
        </message>
        <message>
            <source>I/O points:</source>
            <translation>I/O 點數：</translation>
        </message>
        <message>
            <source>OS version:</source>
            <translation>OS 版本：</translation>
        </message>
        <message>
            <source>Program size:</source>
            <translation>程式容量：</translation>
        </message>
        <message>
            <source>Digital inputs / outputs:</source>
            <translation>數位輸入 / 輸出：</translation>
        </message>
        <message>
            <source>Analog inputs / outputs:</source>
            <translation>類比輸入 / 輸出：</translation>
        </message>
        <message>
            <source>M / S / L relays:</source>
            <translation>M / S / L 繼電器：</translation>
        </message>
        <message>
            <source>R / D registers:</source>
            <translation>R / D 暫存器：</translation>
        </message>
        <message>
            <source>Timers / counters:</source>
            <translation>計時器 / 計數器：</translation>
        </message>
        <message>
            <source>Raw bytes:</source>
            <translation>原始位元組：</translation>
        </message>
        <message>
            <source>No connection: choose a connection and a station.</source>
            <translation>沒有連線：請選擇連線與站號。</translation>
        </message>
        <message>
            <source>Station %1 on “%2”</source>
            <translation>「%2」上的站號 %1</translation>
        </message>
        <message>
            <source>Read-only (operator) mode: RUN/STOP is disabled.</source>
            <translation>唯讀（操作員）模式：已停用 RUN/STOP。</translation>
        </message>
        <message>
            <source>Put %1 into %2?</source>
            <translation>要將 %1 切換為 %2 嗎？</translation>
        </message>
        <message>
            <source>PLC %1</source>
            <translation>PLC %1</translation>
        </message>
        <message>
            <source>%1 not sent: cancelled.</source>
            <translation>%1 未送出：已取消。</translation>
        </message>
        <message>
            <source>Sending %1…</source>
            <translation>正在送出 %1…</translation>
        </message>
        <message>
            <source>%1 accepted by station %2.</source>
            <translation>站號 %2 已接受 %1。</translation>
        </message>
        <message>
            <source>%1 refused: %2</source>
            <translation>%1 遭拒：%2</translation>
        </message>
        <message>
            <source>Status unknown: %1</source>
            <translation>狀態不明：%1</translation>
        </message>
        <message>
            <source>the PLC sent no status bytes.</source>
            <translation>PLC 未傳回狀態位元組。</translation>
        </message>
        <message>
            <source>Status read at %1.</source>
            <translation>狀態讀取時間：%1。</translation>
        </message>
        <message>
            <source>Not available: %1</source>
            <translation>無法取得：%1</translation>
        </message>
        <message>
            <source>Mode unknown</source>
            <translation>模式不明</translation>
        </message>
        <message>
            <source>(no bytes)</source>
            <translation>（無位元組）</translation>
        </message>
        <message>
            <source>not documented for the binary protocol (see raw bytes)</source>
            <translation>二進位協定未記載（請參閱原始位元組）</translation>
        </message>
        <message>
            <source>main unit MA/MU</source>
            <translation>主機 MA/MU</translation>
        </message>
        <message>
            <source>main unit MC</source>
            <translation>主機 MC</translation>
        </message>
        <message>
            <source>main unit type %1</source>
            <translation>主機類型 %1</translation>
        </message>
        <message>
            <source>code %1</source>
            <translation>代碼 %1</translation>
        </message>
        <message>
            <source>code 0x%1</source>
            <translation>代碼 0x%1</translation>
        </message>
        <message>
            <source>%1 words</source>
            <translation>%1 字組</translation>
        </message>
        <message>
            <source>The link is %1: RUN/STOP waits for it to connect.</source>
            <translation>連線%1：RUN/STOP 須待連線恢復。</translation>
        </message>
        <message>
            <source>M series (the unit does not report its type)</source>
            <translation>M 系列（主機未回報其類型）</translation>
        </message>
        <message>
            <source>not reported</source>
            <translation>未回報</translation>
        </message>
    </context>
    <context>
        <name>Fatek::RawConsole</name>
        <message>
            <source>All directions</source>
            <translation>所有方向</translation>
        </message>
        <message>
            <source>Sent</source>
            <translation>已送出</translation>
        </message>
        <message>
            <source>Received</source>
            <translation>已接收</translation>
        </message>
        <message>
            <source>Events</source>
            <translation>事件</translation>
        </message>
        <message>
            <source>All stations</source>
            <translation>所有站號</translation>
        </message>
        <message>
            <source>Station </source>
            <translation>站號 </translation>
        </message>
        <message>
            <source>All commands</source>
            <translation>所有命令</translation>
        </message>
        <message>
            <source>Errors only</source>
            <translation>僅顯示錯誤</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>暫停</translation>
        </message>
        <message>
            <source>Clear</source>
            <translation>清除</translation>
        </message>
        <message>
            <source>Copy</source>
            <translation>複製</translation>
        </message>
        <message>
            <source>Save…</source>
            <translation>儲存…</translation>
        </message>
        <message>
            <source>No connection: choose a connection to see its traffic.</source>
            <translation>沒有連線：請選擇連線以檢視其通訊內容。</translation>
        </message>
        <message>
            <source>Traffic of “%1” (sending to station %2)</source>
            <translation>「%1」的通訊內容（送往站號 %2）</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>繼續</translation>
        </message>
        <message>
            <source>Paused: new frames are kept in the log and shown on Resume.</source>
            <translation>已暫停：新的訊框會保留在記錄中，按「繼續」後顯示。</translation>
        </message>
        <message>
            <source>%1 older frames were dropped from the log while paused.</source>
            <translation>暫停期間已從記錄中捨棄 %1 個較舊的訊框。</translation>
        </message>
        <message>
            <source>Older frames were not kept while the console was closed; the newest are shown.</source>
            <translation>主控台關閉期間未保留較舊的訊框；目前顯示最新的訊框。</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>無法寫入 %1：%2</translation>
        </message>
        <message>
            <source>Save traffic</source>
            <translation>儲存通訊內容</translation>
        </message>
        <message>
            <source>Tab-separated text (*.tsv *.txt)</source>
            <translation>定位字元分隔文字檔 (*.tsv *.txt)</translation>
        </message>
        <message>
            <source>Saved to %1.</source>
            <translation>已儲存到 %1。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::RawSendBar</name>
        <message>
            <source>Hex</source>
            <translation>十六進位</translation>
        </message>
        <message>
            <source>ASCII</source>
            <translation>ASCII</translation>
        </message>
        <message>
            <source>Send</source>
            <translation>送出</translation>
        </message>
        <message>
            <source>No connection.</source>
            <translation>沒有連線。</translation>
        </message>
        <message>
            <source>Add STX, LRC, ETX (FACON)</source>
            <translation>加上 STX、LRC、ETX (FACON)</translation>
        </message>
        <message>
            <source>Add header, length, CRC (binary)</source>
            <translation>加上標頭、長度、CRC（二進位）</translation>
        </message>
        <message>
            <source>body in hex, e.g. 30 31 34 30</source>
            <translation>十六進位內容，例如 30 31 34 30</translation>
        </message>
        <message>
            <source>body, e.g. 014603R00012</source>
            <translation>內容，例如 014603R00012</translation>
        </message>
        <message>
            <source>payload, e.g. 01 46 03 52 00 0C</source>
            <translation>資料內容，例如 01 46 03 52 00 0C</translation>
        </message>
        <message>
            <source>payload as ASCII</source>
            <translation>ASCII 資料內容</translation>
        </message>
        <message>
            <source>whole frame in hex, e.g. 02 30 31 34 30 43 37 03</source>
            <translation>完整訊框（十六進位），例如 02 30 31 34 30 43 37 03</translation>
        </message>
        <message>
            <source>whole frame, e.g. &lt;STX&gt;0140C7&lt;ETX&gt;</source>
            <translation>完整訊框，例如 &lt;STX&gt;0140C7&lt;ETX&gt;</translation>
        </message>
        <message>
            <source>an unrecognized frame</source>
            <translation>無法辨識的訊框</translation>
        </message>
        <message>
            <source>Send %1 (%2) on %3? It may change the PLC.</source>
            <translation>要在 %3 上送出 %1（%2）嗎？這可能會變更 PLC。</translation>
        </message>
        <message>
            <source>Send raw frame</source>
            <translation>送出原始訊框</translation>
        </message>
        <message>
            <source>Cancelled: nothing sent.</source>
            <translation>已取消：未送出任何資料。</translation>
        </message>
        <message>
            <source>Sending %1
waiting for the answer …</source>
            <translation>送出中 %1
等待回應 …</translation>
        </message>
        <message>
            <source>Not sent: %1
%2</source>
            <translation>未送出：%1
%2</translation>
        </message>
        <message>
            <source>Sent    %1</source>
            <translation>已送出  %1</translation>
        </message>
        <message>
            <source>%1
Failed  %2</source>
            <translation>%1
失敗    %2</translation>
        </message>
        <message>
            <source>%1
Answer  %2
        %3
Meaning %4</source>
            <translation>%1
回應    %2
        %3
意義    %4</translation>
        </message>
        <message>
            <source>%1 (command %2) to station %3</source>
            <translation>%1（命令 %2）至站號 %3</translation>
        </message>
        <message>
            <source>unknown command %1 to station %2</source>
            <translation>未知命令 %1 至站號 %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::StatusIndicator</name>
        <message>
            <source>on</source>
            <translation>開</translation>
        </message>
        <message>
            <source>off</source>
            <translation>關</translation>
        </message>
        <message>
            <source>unknown</source>
            <translation>不明</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TableLogger</name>
        <message>
            <source>No watch table to log.</source>
            <translation>沒有可記錄的監看表。</translation>
        </message>
        <message>
            <source>removed from the table</source>
            <translation>已從監看表移除</translation>
        </message>
        <message>
            <source>format changed</source>
            <translation>格式已變更</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ToolConfirmation</name>
        <message>
            <source>station %1 on “%2”</source>
            <extracomment>How every question names its target: station 1 on “Line 3 (TCP 10.0.0.5:500)”.</extracomment>
            <translation>「%2」上的站號 %1</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ProgramTransferDialog</name>
        <message>
            <source>STOP: %1</source>
            <translation>STOP：%1</translation>
        </message>
        <message>
            <source>%1 RUN: %2</source>
            <translation>%1 RUN：%2</translation>
        </message>
        <message>
            <source>Program Backup / Restore</source>
            <translation>程式備份／還原</translation>
        </message>
        <message>
            <source>&amp;Back Up to File…</source>
            <translation>備份至檔案(&amp;B)…</translation>
        </message>
        <message>
            <source>Read the PLC's program (every page) and save it in a file</source>
            <translation>讀取 PLC 的程式（每一頁）並存入檔案</translation>
        </message>
        <message>
            <source>&amp;Restore from File…</source>
            <translation>從檔案還原(&amp;R)…</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>取消</translation>
        </message>
        <message>
            <source>Stop after the page in progress</source>
            <translation>在目前這一頁完成後停止</translation>
        </message>
        <message>
            <source>Program backups (*.fprog *.json);;All files (*)</source>
            <translation>程式備份 (*.fprog *.json);;所有檔案 (*)</translation>
        </message>
        <message>
            <source>Back Up the PLC Program</source>
            <translation>備份 PLC 程式</translation>
        </message>
        <message>
            <source>Restore a PLC Program</source>
            <translation>還原 PLC 程式</translation>
        </message>
        <message>
            <source>The PLC at %1 is in RUN. A program can only be written in STOP.

Switch the PLC to STOP now?</source>
            <translation>%1 的 PLC 處於 RUN。程式只能在 STOP 時寫入。

現在將 PLC 切換至 STOP 嗎？</translation>
        </message>
        <message>
            <source>Restore Program</source>
            <translation>還原程式</translation>
        </message>
        <message>
            <source>Not restored: the PLC stays in RUN. Nothing was written.</source>
            <translation>未還原：PLC 維持 RUN。未寫入任何資料。</translation>
        </message>
        <message>
            <source>STOP failed: %1</source>
            <translation>STOP 失敗：%1</translation>
        </message>
        <message>
            <source>%1 The PLC is in RUN.</source>
            <translation>%1 PLC 已在 RUN。</translation>
        </message>
        <message>
            <source>%1 RUN failed: %2 The PLC stays in STOP.</source>
            <translation>%1 RUN 失敗：%2 PLC 維持 STOP。</translation>
        </message>
        <message>
            <source>%1 The PLC stays in STOP: check the program before switching it to RUN.</source>
            <translation>%1 PLC 維持 STOP：切換至 RUN 前請先檢查程式。</translation>
        </message>
        <message>
            <source>%1

The PLC at %2 was switched to STOP for the restore. Switch it back to RUN now? It runs its program as before.</source>
            <translation>%1

%2 的 PLC 為了還原已切換至 STOP。現在切換回 RUN 嗎？將照原本的程式執行。</translation>
        </message>
        <message>
            <source>%1 The PLC stays in STOP: switch it to RUN when the machine is ready.</source>
            <translation>%1 PLC 維持 STOP：機台準備好後再切換至 RUN。</translation>
        </message>
        <message>
            <source>%1

Switch the PLC at %2 to RUN now? It starts the restored program.</source>
            <translation>%1

現在將 %2 的 PLC 切換至 RUN 嗎？將開始執行還原的程式。</translation>
        </message>
        <message numerus="yes">
            <source>, about %n s left</source>
            <translation>
                <numerusform>，約剩 %n 秒</numerusform>
            </translation>
        </message>
        <message>
            <source>%1: %2 of %3 pages</source>
            <translation>%1：第 %2／%3 頁</translation>
        </message>
        <message>
            <source>Writing %1 of %2 pages, verifying %3 of %2</source>
            <translation>寫入 %1／%2 頁，驗證 %3／%2 頁</translation>
        </message>
        <message>
            <source>%1 Saved in %2.</source>
            <translation>%1 已存入 %2。</translation>
        </message>
        <message>
            <source>Write the program from %1 to the PLC at %2?

Backup: %3%4, %5 pages.
%6

The PLC's program is replaced; every page is read back and compared.</source>
            <translation>將 %1 的程式寫入 %2 的 PLC 嗎？

備份：%3%4，%5 頁。
%6

PLC 的程式將被取代；每一頁都會讀回並比對。</translation>
        </message>
        <message>
            <source>Not restored: nothing was written.</source>
            <translation>未還原：未寫入任何資料。</translation>
        </message>
        <message>
            <source>Read-only (operator) mode: restoring a program is disabled.</source>
            <translation>唯讀（操作員）模式：已停用程式還原。</translation>
        </message>
        <message>
            <source>Write a program backup to the PLC (it must be in STOP)</source>
            <translation>將程式備份寫入 PLC（PLC 必須處於 STOP）</translation>
        </message>
        <message>
            <source>Operator mode: a backup can be made; restoring a program is disabled.</source>
            <translation>操作員模式：可以備份；已停用程式還原。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ToolDocks</name>
        <message>
            <source>PLC Control</source>
            <translation>PLC 控制</translation>
        </message>
        <message>
            <source>Forcing</source>
            <translation>強制</translation>
        </message>
        <message>
            <source>Raw Console</source>
            <translation>原始訊框主控台</translation>
        </message>
        <message>
            <source>&amp;Loopback Test…</source>
            <translation>迴路測試(&amp;L)…</translation>
        </message>
        <message>
            <source>Scan &amp;Stations…</source>
            <translation>掃描站號(&amp;S)…</translation>
        </message>
        <message>
            <source>Scan Stations: open a connection first.</source>
            <translation>掃描站號：請先開啟連線。</translation>
        </message>
        <message>
            <source>Find the PLCs that answer on the current connection's link</source>
            <translation>找出目前連線上有回應的 PLC</translation>
        </message>
        <message>
            <source>&amp;Program Backup / Restore…</source>
            <translation>程式備份／還原(&amp;P)…</translation>
        </message>
        <message>
            <source>Save the PLC's program in a file, or write a saved one back</source>
            <translation>將 PLC 的程式存入檔案，或將已儲存的程式寫回</translation>
        </message>
        <message>
            <source>Memory S&amp;napshot…</source>
            <translation>記憶體快照(&amp;N)…</translation>
        </message>
        <message>
            <source>Save, compare and restore element values of the current station</source>
            <translation>儲存、比較並還原目前站號的元件數值</translation>
        </message>
        <message>
            <source>Not available through an MQTT gateway connection: this tool needs a direct link to the PLC.</source>
            <translation>透過 MQTT 閘道器連線時無法使用：此工具需要直接連線至 PLC。</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>I/O &amp;Checkout…</source>
            <translation>I/O 點檢(&amp;C)…</translation>
        </message>
        <message>
            <source>Check every input, output and analog point of a machine and write the report</source>
            <translation>逐一檢查機台的每個輸入、輸出與類比點，並寫出報告</translation>
        </message>
        <message>
            <source>%1 — %2, station %3</source>
            <translation>%1 — %2，站號 %3</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrafficLogModel</name>
        <message>
            <source>sent</source>
            <translation>送出</translation>
        </message>
        <message>
            <source>received</source>
            <translation>接收</translation>
        </message>
        <message>
            <source>event</source>
            <translation>事件</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>時間</translation>
        </message>
        <message>
            <source>Direction</source>
            <translation>方向</translation>
        </message>
        <message>
            <source>Station</source>
            <translation>站號</translation>
        </message>
        <message>
            <source>Bytes (hex)</source>
            <translation>位元組（十六進位）</translation>
        </message>
        <message>
            <source>ASCII</source>
            <translation>ASCII</translation>
        </message>
        <message>
            <source>Meaning</source>
            <translation>意義</translation>
        </message>
        <message>
            <source>Error</source>
            <translation>錯誤</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendChartView</name>
        <message>
            <source>no value</source>
            <translation>無數值</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendLogging</name>
        <message>
            <source>Trend</source>
            <translation>趨勢圖</translation>
        </message>
        <message>
            <source>&amp;Trend</source>
            <translation>趨勢圖(&amp;T)</translation>
        </message>
        <message>
            <source>Start &amp;Data Logging…</source>
            <translation>開始資料記錄(&amp;D)…</translation>
        </message>
        <message>
            <source>Write every value of the current watch table to a CSV file with timestamps</source>
            <translation>將目前監看表的每個數值連同時間戳記寫入 CSV 檔</translation>
        </message>
        <message>
            <source>Stop Data Lo&amp;gging</source>
            <translation>停止資料記錄(&amp;G)</translation>
        </message>
        <message>
            <source>Data logging stopped: %1</source>
            <translation>資料記錄已停止：%1</translation>
        </message>
        <message>
            <source>Data Logging</source>
            <translation>資料記錄</translation>
        </message>
        <message>
            <source>Data logging stopped:
%1</source>
            <translation>資料記錄已停止：
%1</translation>
        </message>
        <message>
            <source>No watch table to log.</source>
            <translation>沒有可記錄的監看表。</translation>
        </message>
        <message>
            <source>Logging %1 to %2.</source>
            <translation>正在將 %1 記錄到 %2。</translation>
        </message>
        <message numerus="yes">
            <source>Logging stopped: %n row(s) in %1.</source>
            <translation>
                <numerusform>記錄已停止：%1 中共 %n 列。</numerusform>
            </translation>
        </message>
        <message>
            <source>Add items to a watch table first: logging writes the rows of the current table.</source>
            <translation>請先在監看表中加入項目：資料記錄會寫入目前監看表的各列。</translation>
        </message>
        <message>
            <source>Log Watch Table to CSV</source>
            <translation>將監看表記錄到 CSV</translation>
        </message>
        <message numerus="yes">
            <source>Logging to %1 (%n row(s))</source>
            <translation>
                <numerusform>正在記錄到 %1（%n 列）</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendValueAxes</name>
        <message>
            <source>Bits</source>
            <translation>位元</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>數值</translation>
        </message>
    </context>
    <context>
        <name>Fatek::TrendView</name>
        <message>
            <source>Time</source>
            <translation>時間</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>暫停</translation>
        </message>
        <message>
            <source>Freeze the trend (no new points until resumed)</source>
            <translation>凍結趨勢圖（繼續之前不加入新的點）</translation>
        </message>
        <message>
            <source>Reset Zoom</source>
            <translation>重設縮放</translation>
        </message>
        <message>
            <source>Show the whole time window again and follow the present</source>
            <translation>重新顯示整個時間範圍並跟隨目前時間</translation>
        </message>
        <message>
            <source>Remove</source>
            <translation>移除</translation>
        </message>
        <message>
            <source>Remove the selected item from the trend</source>
            <translation>從趨勢圖移除選取的項目</translation>
        </message>
        <message>
            <source>&amp;Remove from Trend</source>
            <translation>從趨勢圖移除(&amp;R)</translation>
        </message>
        <message>
            <source>Select rows in a watch table and choose "Add to Trend" from its context menu.</source>
            <translation>請在監看表中選取列，然後從右鍵選單選擇「加入趨勢圖」。</translation>
        </message>
        <message>
            <source>Window:</source>
            <translation>時間範圍：</translation>
        </message>
        <message>
            <source>%1 (%2)</source>
            <translation>%1（%2）</translation>
        </message>
        <message>
            <source>No watch table row to trend.</source>
            <translation>沒有可加入趨勢圖的監看表列。</translation>
        </message>
        <message>
            <source>%1 is already in the trend.</source>
            <translation>%1 已在趨勢圖中。</translation>
        </message>
        <message>
            <source>%1 is shown as %2, which has no value to plot.</source>
            <translation>%1 以%2顯示，沒有可繪製的數值。</translation>
        </message>
        <message>
            <source>%1 added to the trend.</source>
            <translation>已將 %1 加入趨勢圖。</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>繼續</translation>
        </message>
        <message>
            <source>Station %1, %2</source>
            <translation>站號 %1，%2</translation>
        </message>
        <message>
            <source>Separate Axes</source>
            <translation>分開座標軸</translation>
        </message>
        <message>
            <source>Give every item its own value axis (bits share one); off: one value axis for all items except bits</source>
            <translation>每個項目各有自己的數值軸（位元共用一軸）；關閉：除位元外所有項目共用一個數值軸</translation>
        </message>
        <message numerus="yes">
            <source>%n item(s) added to the trend.</source>
            <translation>
                <numerusform>已將 %n 個項目加入趨勢圖。</numerusform>
            </translation>
        </message>
        <message>
            <source>Drag a rectangle to zoom in, right-click to zoom out, wheel to zoom the time axis, Shift+wheel to scroll it</source>
            <translation>拖曳矩形可放大，按右鍵可縮小，滾輪可縮放時間軸，Shift+滾輪可捲動時間軸</translation>
        </message>
        <message>
            <source>Export Range…</source>
            <translation>匯出範圍…</translation>
        </message>
        <message>
            <source>Write the recorded values of the items in the time range shown to a CSV file</source>
            <translation>將顯示的時間範圍內各項目的記錄數值寫入 CSV 檔案</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchInput</name>
        <message>
            <source>Type an address such as R100, or a range such as R100..R163.</source>
            <translation>請輸入位址（例如 R100）或範圍（例如 R100..R163）。</translation>
        </message>
        <message>
            <source>"%1": %2</source>
            <translation>「%1」：%2</translation>
        </message>
        <message>
            <source>Too many items at once: at most %1.</source>
            <translation>一次加入的項目太多：最多 %1 個。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchListDocument</name>
        <message>
            <source>&amp;Open Watch List…</source>
            <translation>開啟監看清單(&amp;O)…</translation>
        </message>
        <message>
            <source>&amp;Save Watch List…</source>
            <translation>儲存監看清單(&amp;S)…</translation>
        </message>
        <message>
            <source>&amp;Import CSV…</source>
            <translation>匯入 CSV(&amp;I)…</translation>
        </message>
        <message>
            <source>Reopen Last Watch List at Start</source>
            <translation>啟動時重新開啟上次的監看清單</translation>
        </message>
        <message>
            <source>The last watch list %1 cannot be loaded: %2</source>
            <translation>無法載入上次的監看清單 %1：%2</translation>
        </message>
        <message>
            <source>Reopened %1.</source>
            <translation>已重新開啟 %1。</translation>
        </message>
        <message>
            <source>Cannot open %1: %2</source>
            <translation>無法開啟 %1：%2</translation>
        </message>
        <message>
            <source>Open Watch List</source>
            <translation>開啟監看清單</translation>
        </message>
        <message>
            <source>Watch lists (*.json);;All files (*)</source>
            <translation>監看清單 (*.json);;所有檔案 (*)</translation>
        </message>
        <message>
            <source>%1 cannot be loaded:
%2</source>
            <translation>無法載入 %1：
%2</translation>
        </message>
        <message>
            <source>Loaded %1.</source>
            <translation>已載入 %1。</translation>
        </message>
        <message>
            <source>Save Watch List</source>
            <translation>儲存監看清單</translation>
        </message>
        <message>
            <source>Watch lists (*.json)</source>
            <translation>監看清單 (*.json)</translation>
        </message>
        <message>
            <source>Saved %1.</source>
            <translation>已儲存 %1。</translation>
        </message>
        <message>
            <source>Import CSV</source>
            <translation>匯入 CSV</translation>
        </message>
        <message>
            <source>CSV files (*.csv *.txt);;All files (*)</source>
            <translation>CSV 檔案 (*.csv *.txt);;所有檔案 (*)</translation>
        </message>
        <message>
            <source>%1 cannot be imported:
%2</source>
            <translation>無法匯入 %1：
%2</translation>
        </message>
        <message>
            <source>Imported %1.</source>
            <translation>已匯入 %1。</translation>
        </message>
        <message>
            <source>Untitled</source>
            <translation>未命名</translation>
        </message>
        <message>
            <source>%1 — Operator mode (read-only)</source>
            <translation>%1 — 操作員模式（唯讀）</translation>
        </message>
        <message>
            <source>Import Names and Co&amp;mments…</source>
            <translation>匯入名稱與註解(&amp;M)…</translation>
        </message>
        <message>
            <source>Read the names and comments of addresses from the ladder project&apos;s comment/symbol list (CSV or tab-separated text)</source>
            <translation>從階梯圖專案的註解／符號清單（CSV 或以定位字元分隔的文字）讀取位址的名稱與註解</translation>
        </message>
        <message>
            <source>%1 cannot be imported: %2</source>
            <translation>無法匯入 %1：%2</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>Import Names and Comments</source>
            <translation>匯入名稱與註解</translation>
        </message>
        <message>
            <source>Comment/symbol lists (*.csv *.txt *.tsv);;All files (*)</source>
            <translation>註解／符號清單 (*.csv *.txt *.tsv);;所有檔案 (*)</translation>
        </message>
        <message>
            <source>The watch list %1 has changes that are not saved.</source>
            <translation>監看清單 %1 有尚未儲存的變更。</translation>
        </message>
        <message>
            <source>(untitled)</source>
            <translation>（未命名）</translation>
        </message>
        <message>
            <source>Save them first?</source>
            <translation>要先儲存嗎？</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchTableModel</name>
        <message>
            <source>good</source>
            <translation>良好</translation>
        </message>
        <message>
            <source>late</source>
            <translation>延遲</translation>
        </message>
        <message>
            <source>stale</source>
            <translation>過時</translation>
        </message>
        <message>
            <source>error</source>
            <translation>錯誤</translation>
        </message>
        <message>
            <source>%1, words swapped</source>
            <translation>%1，字組對調</translation>
        </message>
        <message>
            <source>waiting</source>
            <translation>等待中</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>No value yet</source>
            <translation>尚無數值</translation>
        </message>
        <message>
            <source>The gateway&apos;s name for this item; type a name to use your own.</source>
            <translation>此名稱來自閘道器的監看清單；輸入名稱即改用您自己的。</translation>
        </message>
        <message>
            <source>Click the box to toggle</source>
            <translation>按一下方塊可切換</translation>
        </message>
        <message>
            <source>Double-click or F2 to write</source>
            <translation>按兩下或按 F2 寫入</translation>
        </message>
        <message>
            <source>%1 .. %2 (%3 elements)</source>
            <translation>%1 .. %2（%3 個元件）</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>名稱</translation>
        </message>
        <message>
            <source>Address</source>
            <translation>位址</translation>
        </message>
        <message>
            <source>Station</source>
            <translation>站號</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>數值</translation>
        </message>
        <message>
            <source>Format</source>
            <translation>格式</translation>
        </message>
        <message>
            <source>Quality</source>
            <translation>品質</translation>
        </message>
        <message>
            <source>Last update</source>
            <translation>最後更新</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>註解</translation>
        </message>
        <message>
            <source>Station must be a number from 1 to 254.</source>
            <translation>站號必須是 1 到 254 之間的數字。</translation>
        </message>
        <message>
            <source>Unknown format "%1".</source>
            <translation>未知的格式「%1」。</translation>
        </message>
        <message>
            <source>no answer</source>
            <translation>沒有回應</translation>
        </message>
        <message>
            <source>No answer from station %1: check the station number, the PLC's power and the cable.</source>
            <translation>站號 %1 沒有回應：請檢查站號、PLC 電源與線路。</translation>
        </message>
        <message>
            <source>Forced: disabled from the ladder, it keeps the value written to it (Tools ▸ Forcing lists and enables forced points).</source>
            <translation>強制中：已脫離階梯圖控制，保持寫入的值（工具 ▸ 強制 可列出並啟用強制中的點）。</translation>
        </message>
        <message>
            <source>%1 s</source>
            <translation>%1 秒</translation>
        </message>
        <message>
            <source>%1 min</source>
            <translation>%1 分</translation>
        </message>
        <message>
            <source>%1 h</source>
            <translation>%1 小時</translation>
        </message>
        <message>
            <source>%1, %2</source>
            <comment>quality, age of the value</comment>
            <translation>%1，%2</translation>
        </message>
        <message numerus="yes">
            <source>%n alarm(s) defined (Alarms… in the context menu, Ctrl+Shift+A)</source>
            <translation>
                <numerusform>已定義 %n 個警報（右鍵選單的「警報…」，Ctrl+Shift+A）</numerusform>
            </translation>
        </message>
        <message>
            <source>Recorded in the history (deadband %1, heartbeat %2 s)</source>
            <translation>已記錄到歷史資料（不感帶 %1，心跳週期 %2 秒）</translation>
        </message>
        <message>
            <source>ON</source>
            <translation>導通</translation>
        </message>
        <message>
            <source>OFF</source>
            <translation>斷開</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchTableEdits</name>
        <message numerus="yes">
            <source>Add %n item(s)</source>
            <translation>
                <numerusform>新增 %n 個項目</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Remove %n item(s)</source>
            <translation>
                <numerusform>移除 %n 個項目</numerusform>
            </translation>
        </message>
        <message>
            <source>Move Up</source>
            <translation>上移</translation>
        </message>
        <message>
            <source>Move Down</source>
            <translation>下移</translation>
        </message>
        <message numerus="yes">
            <source>Move %n item(s)</source>
            <translation>
                <numerusform>移動 %n 個項目</numerusform>
            </translation>
        </message>
        <message>
            <source>Edit %1</source>
            <translation>編輯 %1</translation>
        </message>
        <message>
            <source>Set Format</source>
            <translation>設定格式</translation>
        </message>
        <message>
            <source>Alarms of %1</source>
            <translation>%1 的警報</translation>
        </message>
        <message>
            <source>Record in History</source>
            <translation>記錄到歷史資料</translation>
        </message>
        <message>
            <source>Stop Recording</source>
            <translation>停止記錄</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchTableWidget</name>
        <message>
            <source>Watch</source>
            <translation>監看</translation>
        </message>
        <message>
            <source>Add: R100, R100..R163, X0..X15 — Enter</source>
            <translation>加入：R100, R100..R163, X0..X15 — 按 Enter</translation>
        </message>
        <message>
            <source>Add</source>
            <translation>加入</translation>
        </message>
        <message>
            <source>Connection this table polls through</source>
            <translation>此監看表輪詢所用的連線</translation>
        </message>
        <message>
            <source> ms</source>
            <translation> ms</translation>
        </message>
        <message>
            <source>Poll interval of this table</source>
            <translation>此監看表的輪詢間隔</translation>
        </message>
        <message>
            <source>Polled at the intervals %1 is configured with</source>
            <translation>依 %1 設定中的間隔輪詢</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>暫停</translation>
        </message>
        <message>
            <source>Stop polling this table</source>
            <translation>停止輪詢此監看表</translation>
        </message>
        <message>
            <source>Confirm writes</source>
            <translation>寫入前確認</translation>
        </message>
        <message>
            <source>Connection:</source>
            <translation>連線：</translation>
        </message>
        <message>
            <source>Every</source>
            <translation>每隔</translation>
        </message>
        <message>
            <source>polling paused</source>
            <translation>輪詢已暫停</translation>
        </message>
        <message>
            <source>link %1</source>
            <translation>連線%1</translation>
        </message>
        <message>
            <source>link %1: %2</source>
            <translation>連線%1：%2</translation>
        </message>
        <message>
            <source>no connection</source>
            <translation>沒有連線</translation>
        </message>
        <message numerus="yes">
            <source>Added %n item(s).</source>
            <translation>
                <numerusform>已加入 %n 個項目。</numerusform>
            </translation>
        </message>
        <message>
            <source>Cannot paste: %1</source>
            <translation>無法貼上：%1</translation>
        </message>
        <message numerus="yes">
            <source>Pasted %n item(s).</source>
            <translation>
                <numerusform>已貼上 %n 個項目。</numerusform>
            </translation>
        </message>
        <message>
            <source>%1 is connected again; %2 was not written.</source>
            <translation>%1 已重新連線；%2 未寫入。</translation>
        </message>
        <message numerus="yes">
            <source>Added %n item(s), each timer and counter contact with its current value (RT/RC) beside it.</source>
            <translation>
                <numerusform>已加入 %n 個項目，每個計時器與計數器接點旁附上其目前值（RT/RC）。</numerusform>
            </translation>
        </message>
        <message>
            <source>Filter: address, name or comment</source>
            <translation>篩選：位址、名稱或註解</translation>
        </message>
        <message>
            <source>Show only the rows whose address, name or comment contains this text (Ctrl+F)</source>
            <translation>只顯示位址、名稱或註解含有此文字的列（Ctrl+F）</translation>
        </message>
        <message numerus="yes">
            <source>Copied %n row(s).</source>
            <translation>
                <numerusform>已複製 %n 列。</numerusform>
            </translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>繼續</translation>
        </message>
        <message>
            <source>Poll this table again</source>
            <translation>重新輪詢此表格</translation>
        </message>
        <message>
            <source>Rows move only in own order: clear the filter, choose Own Order.</source>
            <translation>列只能在自訂順序中移動：請清除篩選並選擇「自訂順序」。</translation>
        </message>
        <message>
            <source>Operator mode is off; %1 was not written.</source>
            <translation>操作員模式已關閉；%1 未寫入。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchTableWriter</name>
        <message>
            <source>%1 (station %2) = %3</source>
            <translation>%1（站號 %2）= %3</translation>
        </message>
        <message>
            <source>Cannot write %1: the table has no connection.</source>
            <translation>無法寫入 %1：此監看表沒有連線。</translation>
        </message>
        <message>
            <source>Write %1 to the PLC on %2?</source>
            <translation>要將 %1 寫入 %2 上的 PLC 嗎？</translation>
        </message>
        <message>
            <source>Write Value</source>
            <translation>寫入數值</translation>
        </message>
        <message>
            <source>Write of %1 cancelled.</source>
            <translation>已取消寫入 %1。</translation>
        </message>
        <message>
            <source>Writing %1 …</source>
            <translation>正在寫入 %1 …</translation>
        </message>
        <message>
            <source>Wrote %1.</source>
            <translation>已寫入 %1。</translation>
        </message>
        <message>
            <source>Wrote %1. %2</source>
            <translation>已寫入 %1。%2</translation>
        </message>
        <message>
            <source>Write of %1: %2</source>
            <translation>寫入 %1：%2</translation>
        </message>
        <message>
            <source>Write of %1 failed: %2</source>
            <translation>寫入 %1 失敗：%2</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>Operator mode (read-only): %1 cannot be written.</source>
            <translation>操作員模式（唯讀）：無法寫入 %1。</translation>
        </message>
        <message>
            <source>New value for %1 (%2; hex as 0x1A or 1Ah):</source>
            <translation>%1 的新數值（%2；十六進位請寫成 0x1A 或 1Ah）：</translation>
        </message>
    </context>
    <context>
        <name>Fatek::WatchTableActions</name>
        <message>
            <source>&amp;Write Value…</source>
            <translation>寫入數值(&amp;W)…</translation>
        </message>
        <message>
            <source>&amp;Swap Words</source>
            <translation>字組對調(&amp;S)</translation>
        </message>
        <message>
            <source>Low word first for 32- and 64-bit values (some HMIs store floats so)</source>
            <translation>32 與 64 位元數值低字組在前（部分人機介面如此儲存浮點數）</translation>
        </message>
        <message>
            <source>&amp;Copy Rows</source>
            <translation>複製列(&amp;C)</translation>
        </message>
        <message>
            <source>Address, name, value, format, quality and comment of the selected rows as tab-separated text</source>
            <translation>所選各列的位址、名稱、數值、格式、品質與註解，以定位字元分隔的文字</translation>
        </message>
        <message>
            <source>&amp;Paste Items</source>
            <translation>貼上項目(&amp;P)</translation>
        </message>
        <message>
            <source>&amp;Remove</source>
            <translation>移除(&amp;R)</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>復原(&amp;U)</translation>
        </message>
        <message>
            <source>&amp;Redo</source>
            <translation>重做(&amp;R)</translation>
        </message>
        <message>
            <source>Move &amp;Up</source>
            <translation>上移(&amp;U)</translation>
        </message>
        <message>
            <source>Move &amp;Down</source>
            <translation>下移(&amp;D)</translation>
        </message>
        <message>
            <source>Own &amp;Order</source>
            <translation>自訂順序(&amp;O)</translation>
        </message>
        <message>
            <source>Show the rows in the order you gave them, not sorted</source>
            <translation>依您排定的順序顯示各列，不排序</translation>
        </message>
        <message>
            <source>Set &amp;Format</source>
            <translation>設定格式(&amp;F)</translation>
        </message>
        <message>
            <source>Add to &amp;Trend</source>
            <translation>加入趨勢圖(&amp;T)</translation>
        </message>
        <message>
            <source>Plot the selected items over time in the trend view</source>
            <translation>在趨勢圖中繪製選取項目隨時間的變化</translation>
        </message>
    </context>
    <context>
        <name>main</name>
        <message>
            <source>Commissioning and monitoring tool for FATEK PLCs.</source>
            <translation>永宏 FATEK PLC 的試車與監控工具。</translation>
        </message>
        <message>
            <source>Start the embedded PLC simulator (demo ladder) and watch it.</source>
            <translation>啟動內建的 PLC 模擬器（示範階梯圖）並監看。</translation>
        </message>
        <message>
            <source>Operator mode: no writes, RUN/STOP or forcing.</source>
            <translation>操作員模式：不允許寫入、RUN/STOP 或強制。</translation>
        </message>
        <message>
            <source>Render the main window to a PNG file after startup and exit.</source>
            <translation>啟動後將主視窗擷取為 PNG 檔，然後結束。</translation>
        </message>
        <message>
            <source>file</source>
            <translation>檔案</translation>
        </message>
        <message>
            <source>With --screenshot: open a commissioning tool first (connection, control, forcing, console, loopback, program, snapshot, trend).</source>
            <translation>搭配 --screenshot：先開啟一個試車工具（connection、control、forcing、console、loopback、program、snapshot、trend）。</translation>
        </message>
        <message>
            <source>name</source>
            <translation>名稱</translation>
        </message>
        <message>
            <source>User interface language for this run: en or zh_TW (default: the View &gt; Language choice, else the system's).</source>
            <translation>本次執行的介面語言：en 或 zh_TW（預設為「檢視 &gt; 語言」的選擇，否則依系統設定）。</translation>
        </message>
        <message>
            <source>code</source>
            <translation>代碼</translation>
        </message>
        <message>
            <source>Watch list to open (.json); with a link option its tables watch that connection.</source>
            <translation>要開啟的監看清單（.json）；搭配連線選項時，其表格監看該連線。</translation>
        </message>
        <message>
            <source>Open a link by URL (tcp://HOST[:PORT], udp://HOST[:PORT], serial://PORT?baud=19200&amp;format=7E1) or by its name in links.conf (@line1).</source>
            <translation>以網址開啟連線（tcp://主機[:埠]、udp://主機[:埠]、serial://埠?baud=19200&amp;format=7E1），或以 links.conf 中的名稱開啟（@line1）。</translation>
        </message>
        <message>
            <source>Open a FATEK link over TCP (port 500 if not given).</source>
            <translation>以 TCP 開啟 FATEK 連線（未指定時埠號為 500）。</translation>
        </message>
        <message>
            <source>Open a FATEK link over UDP (port 500 if not given).</source>
            <translation>以 UDP 開啟 FATEK 連線（未指定時埠號為 500）。</translation>
        </message>
        <message>
            <source>Open a FATEK link on a serial line.</source>
            <translation>在序列埠上開啟 FATEK 連線。</translation>
        </message>
        <message>
            <source>With --serial: speed (9600).</source>
            <translation>搭配 --serial：鮑率（9600）。</translation>
        </message>
        <message>
            <source>With --serial: parity (E).</source>
            <translation>搭配 --serial：同位檢查（E）。</translation>
        </message>
        <message>
            <source>With --serial: data bits (7).</source>
            <translation>搭配 --serial：資料位元（7）。</translation>
        </message>
        <message>
            <source>With --serial: stop bits (1).</source>
            <translation>搭配 --serial：停止位元（1）。</translation>
        </message>
        <message>
            <source>Protocol on the link (auto).</source>
            <translation>連線使用的通訊協定（auto）。</translation>
        </message>
        <message>
            <source>Station number of the link (1).</source>
            <translation>連線的站號（1）。</translation>
        </message>
        <message>
            <source>Answer timeout per attempt (1000).</source>
            <translation>每次嘗試的回應逾時（1000）。</translation>
        </message>
        <message>
            <source>Extra attempts after a timeout (2).</source>
            <translation>逾時後的額外重試次數（2）。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::Connection</name>
        <message>
            <source>%1, no answer from station %2</source>
            <translation>%1，站號 %2 沒有回應</translation>
        </message>
        <message>
            <source>station %1 rests until %2</source>
            <translation>站號 %1 暫停輪詢至 %2</translation>
        </message>
        <message>
            <source>RUN</source>
            <translation>執行</translation>
        </message>
        <message>
            <source>STOP</source>
            <translation>停止</translation>
        </message>
        <message>
            <source>M series</source>
            <translation>M 系列</translation>
        </message>
    </context>
    <context>
        <name>Fatek::StationScanDialog</name>
        <message>
            <source>Scan Stations</source>
            <translation>掃描站號</translation>
        </message>
        <message>
            <source>Asks each station on “%1” for its status (command 40), one at a time, and lists who answers.</source>
            <translation>逐一詢問「%1」上每個站號的狀態（命令 40），並列出有回應的站號。</translation>
        </message>
        <message>
            <source>No connection: open one first.</source>
            <translation>沒有連線：請先開啟連線。</translation>
        </message>
        <message>
            <source>to</source>
            <translation>至</translation>
        </message>
        <message>
            <source>Stations:</source>
            <translation>站號：</translation>
        </message>
        <message>
            <source> ms</source>
            <translation> ms</translation>
        </message>
        <message>
            <source>How long each station has to answer (no retries). 100 ms suits 9600 baud and above; a modem or radio link needs more.</source>
            <translation>每個站號的回應等待時間（不重試）。鮑率 9600 以上用 100 毫秒即可；數據機或無線電連線需要更長。</translation>
        </message>
        <message>
            <source>Wait per station:</source>
            <translation>每站等待：</translation>
        </message>
        <message>
            <source>&amp;Scan</source>
            <translation>掃描(&amp;S)</translation>
        </message>
        <message>
            <source>&amp;Use Station</source>
            <translation>使用此站號(&amp;U)</translation>
        </message>
        <message>
            <source>Make the selected station the one the tools and new tables use</source>
            <translation>讓工具與新的表格使用所選的站號</translation>
        </message>
        <message>
            <source>Scanning stations %1 to %2 …</source>
            <translation>正在掃描站號 %1 至 %2 …</translation>
        </message>
        <message>
            <source>Station %1 — %2</source>
            <translation>站號 %1 — %2</translation>
        </message>
        <message>
            <source> (in use)</source>
            <translation>（使用中）</translation>
        </message>
        <message>
            <source>No station answered. Check the cable, the baud rate and parity, and that the PLCs are powered.</source>
            <translation>沒有站號回應。請檢查線路、鮑率與同位元，以及 PLC 是否已通電。</translation>
        </message>
        <message numerus="yes">
            <source>%n station(s) answered.</source>
            <translation>
                <numerusform>有 %n 個站號回應。</numerusform>
            </translation>
        </message>
        <message>
            <source>“%1” now uses station %2.</source>
            <translation>「%1」現在使用站號 %2。</translation>
        </message>
        <message>
            <source>&amp;Cancel Scan</source>
            <translation>取消掃描(&amp;C)</translation>
        </message>
        <message>
            <source>RUN</source>
            <translation>執行</translation>
        </message>
        <message>
            <source>STOP</source>
            <translation>停止</translation>
        </message>
    </context>
    <context>
        <name>Fatek::SnapshotDialog</name>
        <message>
            <source>Memory Snapshot</source>
            <translation>記憶體快照</translation>
        </message>
        <message>
            <source>R0..R99, M0..M63 (empty: every element the PLC reports)</source>
            <translation>R0..R99, M0..M63（留空：PLC 回報的所有元件）</translation>
        </message>
        <message>
            <source>Ranges:</source>
            <translation>範圍：</translation>
        </message>
        <message>
            <source>Take Snapshot</source>
            <translation>擷取快照</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>取消</translation>
        </message>
        <message>
            <source>Save…</source>
            <translation>儲存…</translation>
        </message>
        <message>
            <source>Open…</source>
            <translation>開啟…</translation>
        </message>
        <message>
            <source>Compare With PLC</source>
            <translation>與 PLC 比較</translation>
        </message>
        <message>
            <source>Compare With File…</source>
            <translation>與檔案比較…</translation>
        </message>
        <message>
            <source>Export Differences…</source>
            <translation>匯出差異…</translation>
        </message>
        <message>
            <source>Filter</source>
            <translation>篩選</translation>
        </message>
        <message>
            <source>Ranges to restore (empty: all but the inputs X)</source>
            <translation>要還原的範圍（留空：輸入 X 以外的全部）</translation>
        </message>
        <message>
            <source>Restore Values…</source>
            <translation>還原數值…</translation>
        </message>
        <message>
            <source>Save Snapshot</source>
            <translation>儲存快照</translation>
        </message>
        <message>
            <source>Open Snapshot</source>
            <translation>開啟快照</translation>
        </message>
        <message>
            <source>Compare With File</source>
            <translation>與檔案比較</translation>
        </message>
        <message>
            <source>Export Differences</source>
            <translation>匯出差異</translation>
        </message>
        <message>
            <source>Snapshots (*.json *.csv)</source>
            <translation>快照 (*.json *.csv)</translation>
        </message>
        <message>
            <source>Stopped: the target changed.</source>
            <translation>已停止：目標已變更。</translation>
        </message>
        <message>
            <source>Snapshot: %1 values, %2, station %3, %4</source>
            <translation>快照：%1 個值，%2，站號 %3，%4</translation>
        </message>
        <message>
            <source>No snapshot yet: take one or open a file.</source>
            <translation>尚無快照：請擷取快照或開啟檔案。</translation>
        </message>
        <message>
            <source>Reading…</source>
            <translation>讀取中…</translation>
        </message>
        <message>
            <source>Snapshot</source>
            <translation>快照</translation>
        </message>
        <message>
            <source>PLC</source>
            <translation>PLC 現值</translation>
        </message>
        <message>
            <source>Saved %1.</source>
            <translation>已儲存 %1。</translation>
        </message>
        <message>
            <source>Before</source>
            <translation>之前</translation>
        </message>
        <message>
            <source>After</source>
            <translation>之後</translation>
        </message>
        <message>
            <source>Opened %1.</source>
            <translation>已開啟 %1。</translation>
        </message>
        <message>
            <source>File</source>
            <translation>檔案</translation>
        </message>
        <message>
            <source>Exported %1 differences to %2.</source>
            <translation>已將 %1 筆差異匯出至 %2。</translation>
        </message>
        <message numerus="yes">
            <source>Write %1 values of the snapshot to %2 in %n request(s), then read them back?</source>
            <translation>
                <numerusform>要以 %n 次請求將快照中的 %1 個值寫入 %2，然後回讀確認嗎？</numerusform>
            </translation>
        </message>
        <message>
            <source>The snapshot is of another model than the PLC at %1.

Snapshot: %2
PLC: %3

Write its values all the same? Elements the PLC does not have are refused before anything is written.</source>
            <translation>快照的機型與 %1 的 PLC 不同。

快照：%2
PLC：%3

仍要寫入其數值嗎？PLC 沒有的元件會在寫入任何資料前被拒絕。</translation>
        </message>
        <message>
            <source>Restore Values</source>
            <translation>還原數值</translation>
        </message>
        <message>
            <source>Not restored: nothing was written.</source>
            <translation>未還原：未寫入任何資料。</translation>
        </message>
        <message>
            <source>Writing…</source>
            <translation>寫入中…</translation>
        </message>
        <message>
            <source>Written</source>
            <translation>已寫入</translation>
        </message>
        <message>
            <source>Read back</source>
            <translation>回讀</translation>
        </message>
        <message numerus="yes">
            <source>The memory snapshot of %n value(s) taken at %1 from station %2 is not saved.</source>
            <translation>
                <numerusform>於 %1 從站號 %2 擷取的記憶體快照（%n 個值）尚未儲存。</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>Fatek::CheckoutTableModel</name>
        <message>
            <source>forced: seen?</source>
            <translation>強制中：看到了嗎？</translation>
        </message>
        <message>
            <source>now %1</source>
            <translation>目前 %1</translation>
        </message>
        <message>
            <source>%1; now %2</source>
            <translation>%1；目前 %2</translation>
        </message>
        <message>
            <source>Group</source>
            <translation>群組</translation>
        </message>
        <message>
            <source>Point</source>
            <translation>點位</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>名稱</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>種類</translation>
        </message>
        <message>
            <source>State</source>
            <translation>狀態</translation>
        </message>
        <message>
            <source>Times / values</source>
            <translation>時間 / 數值</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>備註</translation>
        </message>
        <message>
            <source>%1 %: %2 expected</source>
            <translation>%1 %：預期 %2</translation>
        </message>
        <message>
            <source>Attempt %1: %2, %3 by %4</source>
            <translation>第 %1 次：%2，%3，%4</translation>
        </message>
        <message>
            <source>(no name)</source>
            <translation>（未署名）</translation>
        </message>
        <message>
            <source>%1 (attempt %2)</source>
            <translation>%1（第 %2 次）</translation>
        </message>
        <message>
            <source>no scale: import a plan CSV with it</source>
            <translation>沒有刻度：請匯入含刻度的計畫 CSV</translation>
        </message>
        <message>
            <source>%1; next %2</source>
            <translation>%1；下一個 %2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::CheckoutKeys</name>
        <message>
            <source>Space: passed (an output is forced first), F: failed, R: passed with remark, D: deferred, A: not applicable, T: test again, N: next point, V: read the next analog check, Shift+V: read it again as left, F2: comment</source>
            <translation>空白鍵：合格（輸出先強制），F：不合格，R：合格附註記，D：延後，A：不適用，T：重新測試，N：下一點，V：讀取下一個類比檢查點，Shift+V：調整後再讀一次，F2：備註</translation>
        </message>
        <message>
            <source>%1 (%2)</source>
            <translation>%1（%2）</translation>
        </message>
        <message>
            <source>Answer for %1 first (Space: seen, F: not seen).</source>
            <translation>請先回答 %1（空白鍵：看到，F：沒看到）。</translation>
        </message>
        <message>
            <source>Deferred</source>
            <translation>延後</translation>
        </message>
        <message>
            <source>Passed with Remark</source>
            <translation>合格附註記</translation>
        </message>
        <message>
            <source>Why is %1 deferred (what is missing, until when)?</source>
            <translation>%1 為何延後（缺什麼、到何時）？</translation>
        </message>
        <message>
            <source>The remark on %1 (what was not as it should be):</source>
            <translation>%1 的註記（哪裡不如預期）：</translation>
        </message>
        <message>
            <source>Nothing recorded on %1.</source>
            <translation>%1 未記錄任何結果。</translation>
        </message>
        <message>
            <source>%1 is tested again: actuate it in the field.</source>
            <translation>%1 重新測試：請在現場動作。</translation>
        </message>
        <message>
            <source>%1 is tested again: Space forces it.</source>
            <translation>%1 重新測試：按空白鍵強制。</translation>
        </message>
        <message>
            <source>%1 is tested again: V reads its checks.</source>
            <translation>%1 重新測試：按 V 讀取各檢查點。</translation>
        </message>
        <message>
            <source>%1. Import a plan CSV that gives its scale (Import… &gt; Plan CSV…).</source>
            <translation>%1。請匯入含其刻度的計畫 CSV（匯入… &gt; 計畫 CSV…）。</translation>
        </message>
        <message>
            <source>Reading %1…</source>
            <translation>正在讀取 %1…</translation>
        </message>
        <message>
            <source>%1: %2.</source>
            <translation>%1：%2。</translation>
        </message>
        <message>
            <source>%1 read. Next: %2 (V); Shift+V reads the last check again as left.</source>
            <translation>已讀取 %1。下一個：%2（V）；Shift+V 將最後的檢查點再讀一次作為調整後值。</translation>
        </message>
        <message>
            <source>Start the checkout first: outputs are forced only while it runs.</source>
            <translation>請先開始點檢：只有執行中才強制輸出。</translation>
        </message>
        <message>
            <source>Operator mode: outputs are not forced.</source>
            <translation>操作員模式：不強制輸出。</translation>
        </message>
        <message>
            <source>Force %1 on at %2? It stays on until you answer, then it is released.</source>
            <translation>在%2將 %1 強制為 ON？回答前保持 ON，回答後即解除。</translation>
        </message>
        <message>
            <source>Force Output</source>
            <translation>強制輸出</translation>
        </message>
        <message>
            <source>Not forced: nothing was written.</source>
            <translation>未強制：沒有寫入任何資料。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::CheckoutDetailsDialog</name>
        <message>
            <source>Checkout Details</source>
            <translation>點檢詳細資料</translation>
        </message>
        <message>
            <source>Document ID:</source>
            <translation>文件編號：</translation>
        </message>
        <message>
            <source>Revision:</source>
            <translation>版次：</translation>
        </message>
        <message>
            <source>Engineer&apos;s company:</source>
            <translation>工程師公司：</translation>
        </message>
        <message>
            <source>Witness:</source>
            <translation>見證人：</translation>
        </message>
        <message>
            <source>Witness&apos;s company:</source>
            <translation>見證人公司：</translation>
        </message>
        <message>
            <source>Signs for the customer:</source>
            <translation>客戶簽署人：</translation>
        </message>
    </context>
    <context>
        <name>Fatek::CsvFileFilter</name>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>CSV 檔案 (*.csv)</translation>
        </message>
        <message>
            <source>CSV, Windows line ends (*.csv)</source>
            <translation>CSV（Windows 換行）(*.csv)</translation>
        </message>
    </context>
    <context>
        <name>Fatek::CheckoutPunchDialog</name>
        <message>
            <source>Punch List</source>
            <translation>待辦清單</translation>
        </message>
        <message>
            <source>Close Out</source>
            <translation>結案</translation>
        </message>
        <message>
            <source>Close out the chosen item: its point passes now</source>
            <translation>將選取的項目結案：該點位現已合格</translation>
        </message>
        <message>
            <source>Export CSV…</source>
            <translation>匯出 CSV…</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>關閉</translation>
        </message>
        <message>
            <source>Choose the item to close out.</source>
            <translation>請選擇要結案的項目。</translation>
        </message>
        <message>
            <source>Export Punch List</source>
            <translation>匯出待辦清單</translation>
        </message>
        <message>
            <source>%1 is closed out.</source>
            <translation>%1 已結案。</translation>
        </message>
        <message>
            <source>Punch list written: %1</source>
            <translation>待辦清單已寫出：%1</translation>
        </message>
    </context>
    <context>
        <name>Fatek::IoCheckoutDialog</name>
        <message>
            <source>I/O Checkout</source>
            <translation>I/O 點檢</translation>
        </message>
        <message>
            <source>X0..X15, Y0..Y7, R100</source>
            <translation>X0..X15, Y0..Y7, R100</translation>
        </message>
        <message>
            <source>Points:</source>
            <translation>點位：</translation>
        </message>
        <message>
            <source>Project:</source>
            <translation>專案：</translation>
        </message>
        <message>
            <source>Customer:</source>
            <translation>客戶：</translation>
        </message>
        <message>
            <source>Engineer:</source>
            <translation>工程師：</translation>
        </message>
        <message>
            <source>New</source>
            <translation>新增</translation>
        </message>
        <message>
            <source>Open…</source>
            <translation>開啟…</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>開始</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>停止</translation>
        </message>
        <message>
            <source>Report…</source>
            <translation>報告…</translation>
        </message>
        <message>
            <source>Write the report as PDF or CSV</source>
            <translation>寫出報告（可攜文件 *.pdf 或 CSV）</translation>
        </message>
        <message>
            <source>Open Checkout</source>
            <translation>開啟點檢</translation>
        </message>
        <message>
            <source>Checkouts (*.json)</source>
            <translation>點檢檔 (*.json)</translation>
        </message>
        <message>
            <source>Checkout Report</source>
            <translation>點檢報告</translation>
        </message>
        <message>
            <source>Watching the inputs: actuate %1 in the field.</source>
            <translation>正在監看輸入：請在現場動作 %1。</translation>
        </message>
        <message>
            <source>%1 is forced on. Seen in the field? Space: seen, F: not seen.</source>
            <translation>%1 已強制為 ON。現場看到了嗎？空白鍵：看到，F：沒看到。</translation>
        </message>
        <message>
            <source>%1 is released.</source>
            <translation>%1 已解除強制。</translation>
        </message>
        <message>
            <source>Force Output</source>
            <translation>強制輸出</translation>
        </message>
        <message>
            <source>Stopped: the target changed.</source>
            <translation>已停止：目標已變更。</translation>
        </message>
        <message>
            <source>(operator mode: outputs are not forced)</source>
            <translation>（操作員模式：不強制輸出）</translation>
        </message>
        <message>
            <source>Save Checkout</source>
            <translation>儲存點檢</translation>
        </message>
        <message>
            <source>Reading the PLC&apos;s status…</source>
            <translation>正在讀取 PLC 狀態…</translation>
        </message>
        <message>
            <source>Opened %1.</source>
            <translation>已開啟 %1。</translation>
        </message>
        <message>
            <source>The checkout left %1 forced on %2. Release them now?</source>
            <translation>點檢在%2留下強制中的 %1。現在解除嗎？</translation>
        </message>
        <message>
            <source>Release Outputs</source>
            <translation>解除輸出強制</translation>
        </message>
        <message>
            <source>Still forced: %1 (Start releases them).</source>
            <translation>仍在強制中：%1（按「開始」即解除）。</translation>
        </message>
        <message>
            <source>Report written: %1</source>
            <translation>報告已寫出：%1</translation>
        </message>
        <message>
            <source>The latest results of the checkout are not saved: %1</source>
            <translation>點檢最新的結果尚未儲存：%1</translation>
        </message>
        <message>
            <source>Import…</source>
            <translation>匯入…</translation>
        </message>
        <message>
            <source>A plan from a CSV file, or from the names imported in the main window</source>
            <translation>從 CSV 檔或主視窗匯入的名稱建立計畫</translation>
        </message>
        <message>
            <source>Details…</source>
            <translation>詳細資料…</translation>
        </message>
        <message>
            <source>Document ID, revision and who signs the report</source>
            <translation>文件編號、版次及報告簽署人</translation>
        </message>
        <message>
            <source>Punch List…</source>
            <translation>待辦清單…</translation>
        </message>
        <message>
            <source>The failed and deferred points: owner, close-out, CSV</source>
            <translation>不合格及延後的點位：負責人、結案、CSV</translation>
        </message>
        <message>
            <source>Releasing %1… the window closes once the PLC confirms it.</source>
            <translation>正在解除 %1 的強制…PLC 確認後視窗即關閉。</translation>
        </message>
        <message>
            <source>Close I/O Checkout</source>
            <translation>關閉 I/O 點檢</translation>
        </message>
        <message>
            <source>%1 is not confirmed released on %2. Close anyway? The checkout file keeps it listed: the next Open releases it.</source>
            <translation>%2的 %1 尚未確認解除強制。仍要關閉嗎？點檢檔會保留記錄：下次開啟時會解除。</translation>
        </message>
        <message>
            <source>Plan CSV…</source>
            <translation>計畫 CSV…</translation>
        </message>
        <message>
            <source>Import Checkout Plan</source>
            <translation>匯入點檢計畫</translation>
        </message>
        <message>
            <source>Checkout plans (*.csv)</source>
            <translation>點檢計畫 (*.csv)</translation>
        </message>
        <message>
            <source>Imported Names…</source>
            <translation>匯入的名稱…</translation>
        </message>
        <message>
            <source>The names that start with (empty: every name):</source>
            <translation>名稱開頭為（空白：全部名稱）：</translation>
        </message>
        <message>
            <source>PDF…</source>
            <translation>可攜文件報告 (PDF)…</translation>
        </message>
        <message>
            <source>CSV…</source>
            <translation>CSV…</translation>
        </message>
        <message>
            <source>CSV with Windows Line Ends…</source>
            <translation>CSV（Windows 換行）…</translation>
        </message>
        <message>
            <source>PDF reports (*.pdf)</source>
            <translation>可攜文件報告 (*.pdf)</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>CSV 檔案 (*.csv)</translation>
        </message>
        <message numerus="yes">
            <source>Imported %1: %n point(s).</source>
            <translation>
                <numerusform>已匯入 %1：%n 個點位。</numerusform>
            </translation>
        </message>
        <message>
            <source>No names are imported: File &gt; Import Names and Comments… in the main window first.</source>
            <translation>尚未匯入名稱：請先在主視窗使用「檔案 &gt; 匯入名稱與註解…」。</translation>
        </message>
        <message numerus="yes">
            <source>A plan of %n point(s) from the imported names.</source>
            <translation>
                <numerusform>由匯入的名稱建立 %n 個點位的計畫。</numerusform>
            </translation>
        </message>
        <message>
            <source>The report&apos;s details are set.</source>
            <translation>報告的詳細資料已設定。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::ToolDialogFrame</name>
        <message>
            <source>Station %1 on “%2”</source>
            <translation>「%2」上的站號 %1</translation>
        </message>
        <message>
            <source>No connection: choose a connection and a station.</source>
            <translation>沒有連線：請選擇連線與站號。</translation>
        </message>
        <message>
            <source>Save it first? Discarded, it is lost.</source>
            <translation>要先儲存嗎？捨棄後便無法找回。</translation>
        </message>
        <message>
            <source>&amp;Save…</source>
            <translation>儲存(&amp;S)…</translation>
        </message>
        <message>
            <source>&amp;Discard</source>
            <translation>捨棄(&amp;D)</translation>
        </message>
    </context>
    <context>
        <name>Fatek::SnapshotDiffModel</name>
        <message>
            <source>Before</source>
            <translation>之前</translation>
        </message>
        <message>
            <source>After</source>
            <translation>之後</translation>
        </message>
        <message>
            <source>Address</source>
            <translation>位址</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmAnnunciator</name>
        <message>
            <source>&amp;Mute Alarm Sound</source>
            <translation>警報靜音(&amp;M)</translation>
        </message>
        <message>
            <source>Open the alarm summary</source>
            <translation>開啟警報總覽</translation>
        </message>
        <message>
            <source>No sound while alarms wait for an acknowledge</source>
            <translation>警報等待確認時不發出聲音</translation>
        </message>
        <message numerus="yes">
            <source>%n unacknowledged alarm(s)</source>
            <translation>
                <numerusform>%n 個警報未確認</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmCenter</name>
        <message>
            <source>Alarm journal %1: %2</source>
            <translation>警報日誌 %1：%2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmDefinitionDialog</name>
        <message>
            <source> s</source>
            <translation> 秒</translation>
        </message>
        <message>
            <source>Alarms of %1</source>
            <translation>%1 的警報</translation>
        </message>
        <message>
            <source>Alarms of %1 (%2)</source>
            <translation>%1（%2）的警報</translation>
        </message>
        <message>
            <source>Alarm</source>
            <translation>警報</translation>
        </message>
        <message>
            <source>Limit</source>
            <translation>限值</translation>
        </message>
        <message>
            <source>Deadband</source>
            <translation>不感帶</translation>
        </message>
        <message>
            <source>On delay</source>
            <translation>觸發延遲</translation>
        </message>
        <message>
            <source>Off delay</source>
            <translation>解除延遲</translation>
        </message>
        <message>
            <source>Priority</source>
            <translation>優先等級</translation>
        </message>
        <message>
            <source>Message</source>
            <translation>訊息</translation>
        </message>
        <message>
            <source>Group</source>
            <translation>群組</translation>
        </message>
        <message>
            <source>In service</source>
            <translation>啟用</translation>
        </message>
        <message>
            <source>Limits are in the item&apos;s format (%1). A high alarm clears when the value is below its limit by the deadband; the delays say how long a condition must hold before it raises or clears the alarm.</source>
            <translation>限值依此項目的格式（%1）。高警報在數值低於限值超過不感帶時解除；延遲是條件須持續多久才觸發或解除警報。</translation>
        </message>
        <message>
            <source>The delays say how long a condition must hold before it raises or clears the alarm. A bad quality alarm is raised when the item is stale or in error for its on delay.</source>
            <translation>延遲是條件須持續多久才觸發或解除警報。品質不良警報在項目過期或錯誤持續達觸發延遲時觸發。</translation>
        </message>
        <message>
            <source>Off: out of service, never raised (kept in the list)</source>
            <translation>關閉：停用，永不觸發（仍保留在清單中）</translation>
        </message>
        <message>
            <source>%1: type the limit.</source>
            <translation>%1：請輸入限值。</translation>
        </message>
        <message>
            <source>%1: the limit &quot;%2&quot; is not a number.</source>
            <translation>%1：限值「%2」不是數字。</translation>
        </message>
        <message>
            <source>%1: the deadband &quot;%2&quot; is not a number.</source>
            <translation>%1：不感帶「%2」不是數字。</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmEventsModel</name>
        <message>
            <source>%1 until %2</source>
            <translation>%1 至 %2</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>時間</translation>
        </message>
        <message>
            <source>Connection</source>
            <translation>連線</translation>
        </message>
        <message>
            <source>Alarm</source>
            <translation>警報</translation>
        </message>
        <message>
            <source>Event</source>
            <translation>事件</translation>
        </message>
        <message>
            <source>State after</source>
            <translation>事件後狀態</translation>
        </message>
        <message>
            <source>Priority</source>
            <translation>優先等級</translation>
        </message>
        <message>
            <source>Message</source>
            <translation>訊息</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>數值</translation>
        </message>
        <message>
            <source>User</source>
            <translation>使用者</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>註解</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmJournalDialog</name>
        <message>
            <source>&amp;Show</source>
            <translation>顯示(&amp;S)</translation>
        </message>
        <message>
            <source>&amp;Export CSV…</source>
            <translation>匯出 CSV(&amp;E)…</translation>
        </message>
        <message>
            <source>Alarm Journal</source>
            <translation>警報日誌</translation>
        </message>
        <message>
            <source>All connections</source>
            <translation>所有連線</translation>
        </message>
        <message>
            <source>From:</source>
            <translation>從：</translation>
        </message>
        <message>
            <source>To:</source>
            <translation>到：</translation>
        </message>
        <message>
            <source>Connection:</source>
            <translation>連線：</translation>
        </message>
        <message>
            <source>The end of the range must come after its start.</source>
            <translation>範圍的結束須晚於開始。</translation>
        </message>
        <message>
            <source>Reading the journal…</source>
            <translation>正在讀取日誌…</translation>
        </message>
        <message>
            <source>The journal could not be read: %1</source>
            <translation>無法讀取日誌：%1</translation>
        </message>
        <message numerus="yes">
            <source>%n event(s).</source>
            <translation>
                <numerusform>%n 筆事件。</numerusform>
            </translation>
        </message>
        <message>
            <source>Export Alarm Journal</source>
            <translation>匯出警報日誌</translation>
        </message>
        <message>
            <source>All files (*)</source>
            <translation>所有檔案 (*)</translation>
        </message>
        <message>
            <source>Not exported: %1</source>
            <translation>未匯出：%1</translation>
        </message>
        <message numerus="yes">
            <source>%n event(s) written to %1.</source>
            <translation>
                <numerusform>已將 %n 筆事件寫入 %1。</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmsUi</name>
        <message>
            <source>Alarms</source>
            <translation>警報</translation>
        </message>
        <message>
            <source>&amp;Alarm Summary</source>
            <translation>警報總覽(&amp;A)</translation>
        </message>
        <message>
            <source>Alarm &amp;Journal…</source>
            <translation>警報日誌(&amp;J)…</translation>
        </message>
        <message>
            <source>&amp;Alarms…</source>
            <translation>警報(&amp;A)…</translation>
        </message>
        <message>
            <source>Limits, bit and quality alarms of the row (not in operator mode)</source>
            <translation>此列的限值、位元與品質警報（操作員模式下不可用）</translation>
        </message>
        <message>
            <source>Operator mode: alarm definitions cannot be changed.</source>
            <translation>操作員模式：無法變更警報定義。</translation>
        </message>
        <message>
            <source>Select the row whose alarms to edit.</source>
            <translation>請選取要編輯警報的列。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmSummaryModel</name>
        <message>
            <source>shelved until %1</source>
            <translation>擱置至 %1</translation>
        </message>
        <message>
            <source>%1, chattering</source>
            <translation>%1，頻繁觸發</translation>
        </message>
        <message>
            <source>State</source>
            <translation>狀態</translation>
        </message>
        <message>
            <source>Priority</source>
            <translation>優先等級</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>時間</translation>
        </message>
        <message>
            <source>Connection</source>
            <translation>連線</translation>
        </message>
        <message>
            <source>Item</source>
            <translation>項目</translation>
        </message>
        <message>
            <source>Message</source>
            <translation>訊息</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>數值</translation>
        </message>
        <message>
            <source>Group</source>
            <translation>群組</translation>
        </message>
        <message>
            <source>%1 (%2, station %3)</source>
            <translation>%1（%2，站號 %3）</translation>
        </message>
        <message>
            <source>Chattering: raised %1 times or more within a minute.</source>
            <translation>頻繁觸發：一分鐘內觸發 %1 次以上。</translation>
        </message>
        <message>
            <source>Last action by %1</source>
            <translation>最後操作者：%1</translation>
        </message>
        <message>
            <source>Last action by %1: %2</source>
            <translation>最後操作者：%1：%2</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmSummaryWidget</name>
        <message>
            <source>All priorities</source>
            <translation>所有優先等級</translation>
        </message>
        <message>
            <source>All states</source>
            <translation>所有狀態</translation>
        </message>
        <message>
            <source>Unacknowledged</source>
            <translation>未確認</translation>
        </message>
        <message>
            <source>Active</source>
            <translation>作用中</translation>
        </message>
        <message>
            <source>Shelved</source>
            <translation>已擱置</translation>
        </message>
        <message>
            <source>Out of service</source>
            <translation>停用</translation>
        </message>
        <message>
            <source>All groups</source>
            <translation>所有群組</translation>
        </message>
        <message>
            <source>Filter: item, message, group or connection</source>
            <translation>篩選：項目、訊息、群組或連線</translation>
        </message>
        <message>
            <source>Comment (optional)</source>
            <translation>註解（選填）</translation>
        </message>
        <message>
            <source>Kept in the journal with the next acknowledge or shelve</source>
            <translation>隨下一次確認或擱置記入日誌</translation>
        </message>
        <message>
            <source>&amp;Acknowledge</source>
            <translation>確認(&amp;A)</translation>
        </message>
        <message>
            <source>Acknowledge All &amp;Shown</source>
            <translation>確認所有顯示的警報(&amp;S)</translation>
        </message>
        <message>
            <source>Acknowledge (Ctrl+K)</source>
            <translation>確認（Ctrl+K）</translation>
        </message>
        <message>
            <source>Acknowledge the selected alarms</source>
            <translation>確認選取的警報</translation>
        </message>
        <message>
            <source>Acknowledge All Shown</source>
            <translation>確認所有顯示的警報</translation>
        </message>
        <message>
            <source>Acknowledge every alarm the filters show (Ctrl+Shift+K)</source>
            <translation>確認篩選後顯示的所有警報（Ctrl+Shift+K）</translation>
        </message>
        <message>
            <source>Shelve</source>
            <translation>擱置</translation>
        </message>
        <message>
            <source>Hide the selected alarms for a while; they come back by themselves</source>
            <translation>暫時隱藏選取的警報；時間到會自動恢復</translation>
        </message>
        <message>
            <source>For 15 min</source>
            <translation>15 分鐘</translation>
        </message>
        <message>
            <source>For 1 h</source>
            <translation>1 小時</translation>
        </message>
        <message>
            <source>For 8 h</source>
            <translation>8 小時</translation>
        </message>
        <message>
            <source>For a Time…</source>
            <translation>自訂時間…</translation>
        </message>
        <message>
            <source>Unshelve</source>
            <translation>取消擱置</translation>
        </message>
        <message>
            <source>Journal…</source>
            <translation>日誌…</translation>
        </message>
        <message>
            <source>Every raise, acknowledge, return and shelve, by time; export to CSV</source>
            <translation>依時間列出每次觸發、確認、恢復與擱置；可匯出 CSV</translation>
        </message>
        <message>
            <source>Select the alarms first (click a row, or the arrow keys).</source>
            <translation>請先選取警報（點選一列，或用方向鍵）。</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>%1 %2</source>
            <translation>%1 %2</translation>
        </message>
        <message>
            <source>Acknowledged: %1.</source>
            <translation>已確認：%1。</translation>
        </message>
        <message>
            <source>No alarm shown waits for an acknowledge.</source>
            <translation>顯示的警報都不需要確認。</translation>
        </message>
        <message>
            <source>Shelved until %1: %2.</source>
            <translation>擱置至 %1：%2。</translation>
        </message>
        <message>
            <source>Shelve Alarms</source>
            <translation>擱置警報</translation>
        </message>
        <message>
            <source>Shelve the selected alarms for (minutes):</source>
            <translation>選取的警報擱置（分鐘）：</translation>
        </message>
        <message>
            <source>Unshelved: %1.</source>
            <translation>已取消擱置：%1。</translation>
        </message>
    </context>
    <context>
        <name>Fatek::AlarmText</name>
        <message>
            <source>normal</source>
            <translation>正常</translation>
        </message>
        <message>
            <source>active, unacknowledged</source>
            <translation>作用中，未確認</translation>
        </message>
        <message>
            <source>active, acknowledged</source>
            <translation>作用中，已確認</translation>
        </message>
        <message>
            <source>returned, unacknowledged</source>
            <translation>已恢復，未確認</translation>
        </message>
        <message>
            <source>shelved</source>
            <translation>已擱置</translation>
        </message>
        <message>
            <source>out of service</source>
            <translation>停用</translation>
        </message>
        <message>
            <source>critical</source>
            <translation>緊急</translation>
        </message>
        <message>
            <source>high</source>
            <translation>高</translation>
        </message>
        <message>
            <source>medium</source>
            <translation>中</translation>
        </message>
        <message>
            <source>low</source>
            <translation>低</translation>
        </message>
        <message>
            <source>High-high</source>
            <translation>高高</translation>
        </message>
        <message>
            <source>High</source>
            <translation>高</translation>
        </message>
        <message>
            <source>Low</source>
            <translation>低</translation>
        </message>
        <message>
            <source>Low-low</source>
            <translation>低低</translation>
        </message>
        <message>
            <source>Bit on (1)</source>
            <translation>位元導通（1）</translation>
        </message>
        <message>
            <source>Bit off (0)</source>
            <translation>位元斷開（0）</translation>
        </message>
        <message>
            <source>Bad quality</source>
            <translation>品質不良</translation>
        </message>
        <message>
            <source>raised</source>
            <translation>觸發</translation>
        </message>
        <message>
            <source>returned</source>
            <translation>恢復</translation>
        </message>
        <message>
            <source>acknowledged</source>
            <translation>確認</translation>
        </message>
        <message>
            <source>unshelved</source>
            <translation>取消擱置</translation>
        </message>
        <message>
            <source>in service</source>
            <translation>啟用</translation>
        </message>
        <message>
            <source>%1 min</source>
            <translation>%1 分鐘</translation>
        </message>
        <message>
            <source>%1 h</source>
            <translation>%1 小時</translation>
        </message>
        <message>
            <source>%1 h %2 min</source>
            <translation>%1 小時 %2 分鐘</translation>
        </message>
    </context>
</TS>
