<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>footpath</name>
    <message>
        <source>Figure</source>
        <translation>指标</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>Path length (between stances)</source>
        <translation>路径长度（支撑相之间）</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Steps (strides of this foot)</source>
        <translation>步数（该脚的跨步数）</translation>
    </message>
    <message>
        <source>Cadence, both feet</source>
        <translation>步频（双脚）</translation>
    </message>
    <message>
        <source>%1 steps/min</source>
        <translation>%1 步/分钟</translation>
    </message>
    <message>
        <source>Mean stride length</source>
        <translation>平均步幅</translation>
    </message>
    <message>
        <source>%1 m (sd %2 m)</source>
        <translation>%1 m（标准差 %2 m）</translation>
    </message>
    <message>
        <source>Mean stride duration</source>
        <translation>平均跨步时长</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Mean stance duration</source>
        <translation>平均支撑相时长</translation>
    </message>
    <message>
        <source>End-to-start distance</source>
        <translation>终点到起点的距离</translation>
    </message>
    <message>
        <source>%1 m = %2 % of the path</source>
        <translation>%1 m = 路径的 %2 %</translation>
    </message>
    <message>
        <source>ARMSE 2D / 3D against the reference</source>
        <translation>相对参考的 ARMSE 2D / 3D</translation>
    </message>
    <message>
        <source>%1 m / %2 m</source>
        <translation>%1 m / %2 m</translation>
    </message>
    <message>
        <source>Loop closure (DBSE)</source>
        <translation>闭合误差（DBSE）</translation>
    </message>
    <message>
        <source>%1 m = %2 %</source>
        <translation>%1 m = %2 %</translation>
    </message>
    <message>
        <source>Distance error</source>
        <translation>距离误差</translation>
    </message>
    <message>
        <source>%1 m = %2 % of %3 m</source>
        <translation>%1 m = %3 m 的 %2 %</translation>
    </message>
    <message>
        <source>Stance detection precision / recall / F1</source>
        <translation>支撑相检测 精确率 / 召回率 / F1</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>步序</translation>
    </message>
    <message>
        <source>Stance from (s)</source>
        <translation>支撑相起 (s)</translation>
    </message>
    <message>
        <source>to (s)</source>
        <translation>止 (s)</translation>
    </message>
    <message>
        <source>Stride (m)</source>
        <translation>步幅 (m)</translation>
    </message>
    <message>
        <source>Stride (s)</source>
        <translation>跨步时长 (s)</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>z (m)</source>
        <translation>z (m)</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>记录</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>格式</translation>
    </message>
    <message>
        <source>Sensor / device</source>
        <translation>传感器 / 设备</translation>
    </message>
    <message>
        <source>not stated in the file</source>
        <translation>文件中未注明</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>时长</translation>
    </message>
    <message>
        <source>%1 s, %2 samples</source>
        <translation>%1 s，%2 个采样点</translation>
    </message>
    <message>
        <source>Sample rate</source>
        <translation>采样率</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Method set</source>
        <translation>所用方法</translation>
    </message>
    <message>
        <source>Report made</source>
        <translation>报告生成时间</translation>
    </message>
    <message>
        <source>Software</source>
        <translation>软件</translation>
    </message>
    <message>
        <source>Footpath %1</source>
        <translation>Footpath %1</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <source>height z (m)</source>
        <translation>高度 z (m)</translation>
    </message>
    <message>
        <source>Figure 6. Stride length per step.</source>
        <translation>图 6. 每步的步幅。</translation>
    </message>
    <message>
        <source>step</source>
        <translation>步序</translation>
    </message>
    <message>
        <source>stride length (m)</source>
        <translation>步幅 (m)</translation>
    </message>
    <message>
        <source>Figure 7. Stance duration per step.</source>
        <translation>图 7. 每步的支撑相时长。</translation>
    </message>
    <message>
        <source>stance phase</source>
        <translation>支撑相</translation>
    </message>
    <message>
        <source>stance duration (s)</source>
        <translation>支撑相时长 (s)</translation>
    </message>
    <message>
        <source>Figure 8. Histograms of stride length (left) and stance duration (right).</source>
        <translation>图 8. 步幅（左）与支撑相时长（右）的直方图。</translation>
    </message>
    <message>
        <source>strides</source>
        <translation>跨步数</translation>
    </message>
    <message>
        <source>stances</source>
        <translation>支撑相数</translation>
    </message>
    <message>
        <source>Figure 1. The foot path seen from above (stance positions as dots; reference dashed when present).</source>
        <translation>图 1. 俯视的足部轨迹（支撑相位置以圆点表示；如有参考轨迹，以虚线表示）。</translation>
    </message>
    <message>
        <source>Figure 2. Height of the foot over time.</source>
        <translation>图 2. 足部高度随时间的变化。</translation>
    </message>
    <message>
        <source>Figure 3. The path in 3D.</source>
        <translation>图 3. 3D 轨迹。</translation>
    </message>
    <message>
        <source>Figure 4. Signals, stance shaded.</source>
        <translation>图 4. 信号，支撑相以阴影标出。</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>nothing to report: no estimate yet</source>
        <translation>无可报告的内容：尚无估计结果</translation>
    </message>
    <message>
        <source>Footpath report: %1</source>
        <translation>Footpath 报告：%1</translation>
    </message>
    <message>
        <source>%1: cannot write the PDF</source>
        <translation>%1：无法写入 PDF</translation>
    </message>
    <message>
        <source>Footpath report</source>
        <translation>Footpath 报告</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>摘要</translation>
    </message>
    <message>
        <source>Figures</source>
        <translation>图表</translation>
    </message>
    <message>
        <source>Parameters (* differs from the default)</source>
        <translation>参数（* 表示与默认值不同）</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>各步</translation>
    </message>
    <message>
        <source>Figure 5. Stance detector C1/C2/C3 from %1 s to %2 s: conditions C1, C2, C3, their combination C, the median-filtered stance, the std of |a| on a logarithmic axis, and the inputs with their thresholds; plausibility warnings shaded red.</source>
        <translation>图 5. 支撑相检测器 C1/C2/C3，%1 s 至 %2 s：条件 C1、C2、C3 及其组合 C，中值滤波后的支撑相，对数坐标上的 |a| 标准差，以及各输入及其阈值；合理性警告以红色阴影标出。</translation>
    </message>
    <message>
        <source>Figure 5. Stance detector %3 from %1 s to %2 s: the condition C (statistic below threshold), the stance, and the statistic on a logarithmic axis with its threshold; plausibility warnings shaded red.</source>
        <translation>图 5. 支撑相检测器 %3，%1 s 至 %2 s：条件 C（统计量低于阈值）、支撑相，以及对数坐标上的统计量及其阈值；合理性警告以红色阴影标出。</translation>
    </message>
    <message>
        <source>Plausibility warnings</source>
        <translation>合理性警告</translation>
    </message>
    <message>
        <source>The plausibility checks found nothing: the result looks like human gait.</source>
        <translation>合理性检查未发现问题：结果符合人类步态。</translation>
    </message>
    <message>
        <source>Findings: %1. Each marks a span where the result is not what human gait gives, so the path needs care there.</source>
        <translation>发现：%1 项。每项标出一个时间段，该段结果不符合人类步态，因此该处的路径需谨慎看待。</translation>
    </message>
    <message>
        <source>%1, %2: %3</source>
        <translation>%1，%2：%3</translation>
    </message>
    <message>
        <source>Import notes (reading the file)</source>
        <translation>导入说明（读取文件）</translation>
    </message>
    <message>
        <source>Import warning: %1</source>
        <translation>导入警告：%1</translation>
    </message>
    <message>
        <source>Reading the file raised no warnings.</source>
        <translation>读取文件时没有警告。</translation>
    </message>
    <message>
        <source>Method comparison</source>
        <translation>方法比较</translation>
    </message>
    <message>
        <source>Every method set run on this recording with the same detector and noise parameters; the best value of a column is in bold and marked %1.</source>
        <translation>每个方法组合都以相同的检测器和噪声参数在此记录上运行；每列的最佳值以粗体显示并标记 %1。</translation>
    </message>
</context>
<context>
    <name>footpath::AnalysisSession</name>
    <message>
        <source>Change %1</source>
        <translation>更改 %1</translation>
    </message>
</context>
<context>
    <name>footpath::ImportDialog</name>
    <message>
        <source>How to read %1</source>
        <translation>如何读取 %1</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>Import preset:</source>
        <translation>导入预设：</translation>
    </message>
    <message>
        <source>detect</source>
        <translation>自动检测</translation>
    </message>
    <message>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <source>g</source>
        <translation>g</translation>
    </message>
    <message>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <source>deg/s</source>
        <translation>deg/s</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>µs</source>
        <translation>µs</translation>
    </message>
    <message>
        <source>Accelerometer unit:</source>
        <translation>加速度计单位：</translation>
    </message>
    <message>
        <source>Gyroscope unit:</source>
        <translation>陀螺仪单位：</translation>
    </message>
    <message>
        <source>Time unit:</source>
        <translation>时间单位：</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>from the time column</source>
        <translation>取自时间列</translation>
    </message>
    <message>
        <source>Sample rate:</source>
        <translation>采样率：</translation>
    </message>
    <message>
        <source>What each column holds (first lines of the file below):</source>
        <translation>各列的内容（下方为文件的前几行）：</translation>
    </message>
    <message>
        <source>Save as import preset named</source>
        <translation>另存为导入预设，名称</translation>
    </message>
    <message>
        <source>e.g. my-logger</source>
        <translation>例如 my-logger</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>打开</translation>
    </message>
    <message>
        <source>role</source>
        <translation>用途</translation>
    </message>
</context>
<context>
    <name>footpath::LivePanel</name>
    <message>
        <source>A serial port, or type a path such as the emulator&apos;s pseudo-terminal</source>
        <translation>串口，或输入路径，例如模拟器的伪终端</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>刷新</translation>
    </message>
    <message>
        <source>Auto (probe)</source>
        <translation>自动（探测）</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Record...</source>
        <translation>记录...</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>端口：</translation>
    </message>
    <message>
        <source>Baud:</source>
        <translation>波特率：</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>采样率：</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <source>Device ID:</source>
        <translation>设备 ID：</translation>
    </message>
    <message>
        <source>Product code:</source>
        <translation>产品代码：</translation>
    </message>
    <message>
        <source>Firmware:</source>
        <translation>固件：</translation>
    </message>
    <message>
        <source>Counters</source>
        <translation>计数器</translation>
    </message>
    <message>
        <source>Samples:</source>
        <translation>采样点数：</translation>
    </message>
    <message>
        <source>Lost packets:</source>
        <translation>丢失数据包：</translation>
    </message>
    <message>
        <source>Checksum errors:</source>
        <translation>校验和错误：</translation>
    </message>
    <message>
        <source>Resyncs:</source>
        <translation>重新同步：</translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation>正在记录到 %1</translation>
    </message>
    <message>
        <source>Recording starts when connected: %1</source>
        <translation>连接后开始记录：%1</translation>
    </message>
    <message>
        <source>Choose a port or type its path.</source>
        <translation>请选择端口或输入其路径。</translation>
    </message>
    <message>
        <source>Record to</source>
        <translation>记录到</translation>
    </message>
    <message>
        <source>Xsens MT binary (*.mtb)</source>
        <translation>Xsens MT 二进制文件 (*.mtb)</translation>
    </message>
    <message>
        <source>Connecting...</source>
        <translation>正在连接...</translation>
    </message>
    <message>
        <source>Streaming</source>
        <translation>正在接收数据流</translation>
    </message>
    <message>
        <source>Stopping...</source>
        <translation>正在停止...</translation>
    </message>
    <message>
        <source>Recording stopped: %1</source>
        <translation>记录已停止：%1</translation>
    </message>
    <message>
        <source>Recording saved to %1</source>
        <translation>记录已保存到 %1</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>已断开连接</translation>
    </message>
    <message>
        <source>Session ended: %1</source>
        <translation>会话已结束：%1</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>断开连接</translation>
    </message>
    <message>
        <source>Stop recording</source>
        <translation>停止记录</translation>
    </message>
    <message>
        <source>Estimate</source>
        <translation>估计</translation>
    </message>
    <message>
        <source>Latency:</source>
        <translation>延迟：</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <source>Steps:</source>
        <translation>步数：</translation>
    </message>
    <message>
        <source>Distance:</source>
        <translation>距离：</translation>
    </message>
    <message>
        <source>No live estimate: %1</source>
        <translation>无实时估计：%1</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Waiting for samples</source>
        <translation>等待采样</translation>
    </message>
    <message>
        <source>Aligning: keep the foot still for the first %1 s</source>
        <translation>对准中：前 %1 秒请保持脚静止</translation>
    </message>
    <message>
        <source>Estimating, %1 s behind the sensor</source>
        <translation>估计中，落后传感器 %1 秒</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Disconnected: the port went away.</source>
        <translation>已断开：端口已消失。</translation>
    </message>
    <message>
        <source>Complete: every sample estimated, as the offline analysis does</source>
        <translation>完成：所有采样均已估计，与离线分析一致</translation>
    </message>
    <message>
        <source>The stance detector looks this far ahead (its windows are centred on each sample, and a stance is confirmed once it has lasted the minimum duration), so the estimate trails the sensor by up to this delay.</source>
        <translation>支撑相检测器需要向前看这么长的时间（其窗口以每个采样点为中心，且支撑相持续到最短时长后才被确认），因此估计结果最多以这一延迟滞后于传感器。</translation>
    </message>
</context>
<context>
    <name>footpath::LiveViews</name>
    <message>
        <source>Live 2D</source>
        <translation>实时 2D</translation>
    </message>
    <message>
        <source>Live 3D</source>
        <translation>实时 3D</translation>
    </message>
    <message>
        <source>Live signals</source>
        <translation>实时信号</translation>
    </message>
    <message>
        <source>Live detector</source>
        <translation>实时检测器</translation>
    </message>
    <message>
        <source>live</source>
        <translation>实时</translation>
    </message>
</context>
<context>
    <name>footpath::MotionLanes</name>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: steps %2–%3 (%4–%5 s)</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;：第 %2–%3 步（%4–%5 s）</translation>
    </message>
    <message>
        <source>&lt;br&gt;barometric height %1 → %2 m</source>
        <translation>&lt;br&gt;气压高度 %1 → %2 m</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>平地</translation>
    </message>
    <message>
        <source>Stairs up</source>
        <translation>上楼梯</translation>
    </message>
    <message>
        <source>Stairs down</source>
        <translation>下楼梯</translation>
    </message>
    <message>
        <source>Elevator up</source>
        <translation>电梯上行</translation>
    </message>
    <message>
        <source>Elevator down</source>
        <translation>电梯下行</translation>
    </message>
    <message>
        <source>Unclassified</source>
        <translation>未分类</translation>
    </message>
    <message>
        <source>1 floor up by stairs (%1 m)</source>
        <translation>经楼梯上行 1 层（%1 m）</translation>
    </message>
    <message>
        <source>1 floor down by stairs (%1 m)</source>
        <translation>经楼梯下行 1 层（%1 m）</translation>
    </message>
    <message>
        <source>%1 floors up by stairs (%2 m)</source>
        <translation>经楼梯上行 %1 层（%2 m）</translation>
    </message>
    <message>
        <source>%1 floors down by stairs (%2 m)</source>
        <translation>经楼梯下行 %1 层（%2 m）</translation>
    </message>
    <message>
        <source>%1 m up by stairs</source>
        <translation>经楼梯上行 %1 m</translation>
    </message>
    <message>
        <source>%1 m down by stairs</source>
        <translation>经楼梯下行 %1 m</translation>
    </message>
    <message>
        <source>1 elevator ride</source>
        <translation>乘电梯 1 次</translation>
    </message>
    <message>
        <source>%1 elevator rides</source>
        <translation>乘电梯 %1 次</translation>
    </message>
    <message>
        <source>Level walking only: no stairs or elevator</source>
        <translation>仅平地行走：无楼梯或电梯</translation>
    </message>
    <message>
        <source>Magnetometer</source>
        <translation>磁力计</translation>
    </message>
    <message>
        <source>Barometer</source>
        <translation>气压计</translation>
    </message>
    <message>
        <source>Heading drift reduction (HDR)</source>
        <translation>航向漂移抑制（HDR）</translation>
    </message>
    <message>
        <source>Position error reduction (IPER)</source>
        <translation>位置误差抑制（IPER）</translation>
    </message>
    <message>
        <source>Zero navigation acceleration (ZUNA)</source>
        <translation>零导航加速度（ZUNA）</translation>
    </message>
    <message>
        <source>Feliz integrator</source>
        <translation>Feliz 积分器</translation>
    </message>
    <message>
        <source>%1–%2 s</source>
        <translation>%1–%2 s</translation>
    </message>
    <message>
        <source>%1, %2: %3</source>
        <translation>%1，%2：%3</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>运动</translation>
    </message>
    <message>
        <source>Method notes</source>
        <translation>方法说明</translation>
    </message>
    <message>
        <source>barometer present, steps not classified (use_baro off?)</source>
        <translation>有气压计，但步态未分类（use_baro 未开启？）</translation>
    </message>
    <message>
        <source>Colour by motion</source>
        <translation>按运动着色</translation>
    </message>
    <message>
        <source>Colour each stride by its step's motion class (stairs, elevator); needs a barometer</source>
        <translation>按每步的运动类别（楼梯、电梯）为步幅着色；需要气压计</translation>
    </message>
    <message>
        <source>Baro height (m)</source>
        <translation>气压高度 (m)</translation>
    </message>
    <message>
        <source>How the foot got to this step: level, stairs or elevator (from the barometer)</source>
        <translation>脚如何到达这一步：平地、楼梯或电梯（由气压计判断）</translation>
    </message>
    <message>
        <source>Barometric height at this stance against the first one</source>
        <translation>此支撑相相对于第一个支撑相的气压高度</translation>
    </message>
    <message>
        <source>Counted from the barometer's height between steps (seed 004); a floor is 3 m</source>
        <translation>由步间气压高度统计（seed 004）；一层按 3 m 计</translation>
    </message>
    <message>
        <source>Where a measurement method skipped itself or did not apply, and why</source>
        <translation>测量方法跳过或不适用的时段及原因</translation>
    </message>
    <message>
        <source>&lt;b&gt;Motion&lt;/b&gt; (barometer): %1</source>
        <translation>&lt;b&gt;运动&lt;/b&gt;（气压计）：%1</translation>
    </message>
    <message>
        <source>Spans where a measurement method skipped itself or did not apply, and why; the other methods ran on.</source>
        <translation>测量方法跳过或不适用的时段及原因；其他方法照常运行。</translation>
    </message>
    <message>
        <source>Motion (barometer): %1.</source>
        <translation>运动（气压计）：%1。</translation>
    </message>
</context>
<context>
    <name>footpath::MainWindow</name>
    <message>
        <source>Path &amp;colours</source>
        <translation>路径颜色(&amp;C)</translation>
    </message>
    <message>
        <source>One colour</source>
        <translation>单色</translation>
    </message>
    <message>
        <source>By time</source>
        <translation>按时间</translation>
    </message>
    <message>
        <source>By foot speed</source>
        <translation>按脚速</translation>
    </message>
    <message>
        <source>By motion (stairs, elevator)</source>
        <translation>按运动（楼梯、电梯）</translation>
    </message>
    <message>
        <source>Footpath</source>
        <translation>Footpath</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>就绪</translation>
    </message>
    <message>
        <source>Signals</source>
        <translation>信号</translation>
    </message>
    <message>
        <source>Stance detector</source>
        <translation>支撑相检测器</translation>
    </message>
    <message>
        <source>Trajectory 2D</source>
        <translation>2D 轨迹</translation>
    </message>
    <message>
        <source>Trajectory 3D</source>
        <translation>3D 轨迹</translation>
    </message>
    <message>
        <source>Recorded input</source>
        <translation>记录输入</translation>
    </message>
    <message>
        <source>Live input</source>
        <translation>实时输入</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>摘要</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;About Footpath</source>
        <translation>关于 Footpath(&amp;A)</translation>
    </message>
    <message>
        <source>About Footpath</source>
        <translation>关于 Footpath</translation>
    </message>
    <message>
        <source>&lt;b&gt;Footpath %1&lt;/b&gt;&lt;p&gt;Foot-mounted inertial navigation: stance detection, strapdown mechanization and an error-state Kalman filter with zero-velocity updates (Guo et al. 2015).&lt;/p&gt;&lt;p&gt;Sample walk: PyShoe VICON dataset, MIT licence, Copyright (c) 2024 Tā-Hā.&lt;/p&gt;</source>
        <translation>&lt;b&gt;Footpath %1&lt;/b&gt;&lt;p&gt;足部安装式惯性导航：支撑相检测、捷联惯导解算，以及带零速更新（ZUPT）的误差状态卡尔曼滤波器（Guo et al. 2015）。&lt;/p&gt;&lt;p&gt;示例行走数据：PyShoe VICON 数据集，MIT 许可证，Copyright (c) 2024 Tā-Hā。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Open recording...</source>
        <translation>打开记录(&amp;O)...</translation>
    </message>
    <message>
        <source>Open with &amp;import settings...</source>
        <translation>使用导入设置打开(&amp;I)...</translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation>打开记录</translation>
    </message>
    <message>
        <source>Say how to read this file.</source>
        <translation>请指定如何读取此文件。</translation>
    </message>
    <message>
        <source>Export &amp;report (PDF)...</source>
        <translation>导出报告 (PDF)(&amp;R)...</translation>
    </message>
    <message>
        <source>Export &amp;CSV...</source>
        <translation>导出 CSV(&amp;C)...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <source>Reset parameters to &amp;defaults</source>
        <translation>将参数重置为默认值(&amp;D)</translation>
    </message>
    <message>
        <source>Reset to defaults</source>
        <translation>重置为默认值</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Trajectory 2D</source>
        <translation>2D 轨迹(&amp;T)</translation>
    </message>
    <message>
        <source>Trajectory &amp;3D</source>
        <translation>3D 轨迹(&amp;3)</translation>
    </message>
    <message>
        <source>&amp;Signals</source>
        <translation>信号(&amp;S)</translation>
    </message>
    <message>
        <source>Stance &amp;detector</source>
        <translation>支撑相检测器(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Settings</source>
        <translation>设置(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>系统默认</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <source>The new language is used from the next start of Footpath.</source>
        <translation>新语言将在下次启动 Footpath 时生效。</translation>
    </message>
    <message>
        <source>Loading cancelled.</source>
        <translation>已取消加载。</translation>
    </message>
    <message>
        <source>Estimate failed: %1</source>
        <translation>估计失败：%1</translation>
    </message>
    <message>
        <source>defaults</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>adjusted in the window</source>
        <translation>已在窗口中调整</translation>
    </message>
    <message>
        <source>Export report</source>
        <translation>导出报告</translation>
    </message>
    <message>
        <source>There is no estimate to report yet.</source>
        <translation>尚无可生成报告的估计结果。</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Report written to %1</source>
        <translation>报告已写入 %1</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>导出 CSV</translation>
    </message>
    <message>
        <source>There is no estimate to export yet.</source>
        <translation>尚无可导出的估计结果。</translation>
    </message>
    <message>
        <source>Export CSV into folder</source>
        <translation>将 CSV 导出到文件夹</translation>
    </message>
    <message>
        <source>Trajectory, steps, summary and parameters written to %1</source>
        <translation>轨迹、各步、摘要和参数已写入 %1</translation>
    </message>
    <message>
        <source>Recordings (*.txt *.csv *.mtb *.TXT *.CSV);;All files (*)</source>
        <translation>记录 (*.txt *.csv *.mtb *.TXT *.CSV);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Reading %1...</source>
        <translation>正在读取 %1...</translation>
    </message>
    <message>
        <source>Footpath - %1</source>
        <translation>Footpath - %1</translation>
    </message>
    <message>
        <source>%1 samples, %2 steps, path %3 m, end to start %4 m (%5 %), estimated in %6 ms</source>
        <translation>%1 个采样点，%2 步，路径 %3 m，终点至起点 %4 m（%5 %），估计耗时 %6 ms</translation>
    </message>
    <message>
        <source>Estimating...</source>
        <translation>正在估计...</translation>
    </message>
    <message>
        <source>&amp;Live path</source>
        <translation>实时轨迹(&amp;L)</translation>
    </message>
    <message>
        <source>Live si&amp;gnals</source>
        <translation>实时信号(&amp;G)</translation>
    </message>
    <message numerus="yes">
        <source>%n plausibility warning(s): %1</source>
        <translation>
            <numerusform>%n 条合理性警告：%1</numerusform>
        </translation>
    </message>
    <message>
        <source>Method comparison</source>
        <translation>方法比较</translation>
    </message>
    <message>
        <source>&amp;Compare methods</source>
        <translation>比较方法(&amp;C)</translation>
    </message>
    <message>
        <source>Run several method sets on this recording and compare their paths and figures</source>
        <translation>在此记录上运行多个方法组合并比较其路径和指标</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>比较</translation>
    </message>
    <message>
        <source>Methods of the set %1</source>
        <translation>组合 %1 的方法</translation>
    </message>
    <message>
        <source>&amp;Analysis</source>
        <translation>分析(&amp;A)</translation>
    </message>
</context>
<context>
    <name>footpath::ParameterPanel</name>
    <message>
        <source>Reset to defaults</source>
        <translation>重置为默认值</translation>
    </message>
    <message>
        <source>Set every parameter back to its default value (one undo step)</source>
        <translation>将所有参数恢复为默认值（可一步撤销）</translation>
    </message>
    <message>
        <source>Load preset...</source>
        <translation>加载预设...</translation>
    </message>
    <message>
        <source>Save preset...</source>
        <translation>保存预设...</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;Range: %3 to %4 %5&lt;br&gt;Default: %6 %5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;范围：%3 至 %4 %5&lt;br&gt;默认值：%6 %5</translation>
    </message>
    <message>
        <source>Back to the default (%1)</source>
        <translation>恢复默认值（%1）</translation>
    </message>
    <message>
        <source>Reset parameters to defaults</source>
        <translation>将参数重置为默认值</translation>
    </message>
    <message>
        <source>%1 sets values the estimate cannot use: %2</source>
        <translation>%1 设置了估计无法使用的值：%2</translation>
    </message>
    <message>
        <source>Load preset %1</source>
        <translation>加载预设 %1</translation>
    </message>
    <message>
        <source>Load parameter preset</source>
        <translation>加载参数预设</translation>
    </message>
    <message>
        <source>Parameter presets (*.json);;All files (*)</source>
        <translation>参数预设 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Load preset</source>
        <translation>加载预设</translation>
    </message>
    <message>
        <source>The preset was not loaded.

%1</source>
        <translation>预设未加载。

%1</translation>
    </message>
    <message>
        <source>Save parameter preset</source>
        <translation>保存参数预设</translation>
    </message>
    <message>
        <source>Parameter presets (*.json)</source>
        <translation>参数预设 (*.json)</translation>
    </message>
    <message>
        <source>Save preset</source>
        <translation>保存预设</translation>
    </message>
    <message>
        <source>The preset was not saved.

%1</source>
        <translation>预设未保存。

%1</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;In presets and --set: %3&lt;br&gt;Default: %4</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;预设和 --set 中的取值：%3&lt;br&gt;默认值：%4</translation>
    </message>
    <message>
        <source>Not used: only the C1/C2/C3 detector uses it, and %1 is chosen.</source>
        <translation>未使用：仅 C1/C2/C3 检测器使用此参数，当前选择的是 %1。</translation>
    </message>
    <message>
        <source>Not used: the statistic detectors (SHOE, ARED, AMVD, MBGTD) use it, and C1/C2/C3 is chosen.</source>
        <translation>未使用：统计量检测器（SHOE、ARED、AMVD、MBGTD）使用此参数，当前选择的是 C1/C2/C3。</translation>
    </message>
    <message>
        <source>Not used: ARED looks at the gyroscope alone.</source>
        <translation>未使用：ARED 只使用陀螺仪。</translation>
    </message>
    <message>
        <source>Not used: %1 looks at the accelerometer alone.</source>
        <translation>未使用：%1 只使用加速度计。</translation>
    </message>
    <message>
        <source>Not used: the threshold is adaptive (zv_adaptive is on).</source>
        <translation>未使用：阈值为自适应（zv_adaptive 已开启）。</translation>
    </message>
    <message>
        <source>Not used: the threshold is fixed (zv_adaptive is off).</source>
        <translation>未使用：阈值为固定值（zv_adaptive 已关闭）。</translation>
    </message>
    <message>
        <source>Not used: the 9-state filter has no bias states.</source>
        <translation>未使用：9 状态滤波器没有零偏状态。</translation>
    </message>
    <message>
        <source>Not used: ZARU corrects the gyro bias, which the 9-state filter does not estimate.</source>
        <translation>未使用：ZARU 修正陀螺仪零偏，而 9 状态滤波器不估计零偏。</translation>
    </message>
</context>
<context>
    <name>footpath::ReconnectOffer</name>
    <message>
        <source>Reconnect</source>
        <translation>重新连接</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>&lt;b&gt;The device went away:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;设备已断开：&lt;/b&gt;%1</translation>
    </message>
    <message>
        <source>Reconnecting continues the recording in %1.</source>
        <translation>重新连接后将在 %1 中继续录制。</translation>
    </message>
    <message>
        <source>%1 is back: reconnect?</source>
        <translation>%1 已恢复：是否重新连接？</translation>
    </message>
    <message>
        <source>Waiting for %1 to come back (plug the sensor in again)...</source>
        <translation>等待 %1 恢复（请重新插入传感器）...</translation>
    </message>
</context>
<context>
    <name>footpath::RecordedInputPanel</name>
    <message>
        <source>Open recording...</source>
        <translation>打开记录...</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Recent</source>
        <translation>最近</translation>
    </message>
    <message>
        <source>Open a recording: Xsens text export or .mtb log, pyshoe CSV, or any delimited text with time, acceleration and angular rate. You can also drop a file here.</source>
        <translation>打开一个记录：Xsens 文本导出或 .mtb 日志、pyshoe CSV，或任何包含时间、加速度和角速度的分隔文本。也可以将文件拖放到此处。</translation>
    </message>
    <message>
        <source>Reading %1: %p%</source>
        <translation>正在读取 %1：%p%</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>格式</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>采样点数</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>采样率</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>时长</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Channels</source>
        <translation>通道</translation>
    </message>
    <message>
        <source>Units in file</source>
        <translation>文件中的单位</translation>
    </message>
    <message>
        <source>Gaps</source>
        <translation>数据缺口</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1 (about %2 samples lost), longest %3 s</source>
        <translation>%1 处（约丢失 %2 个采样点），最长 %3 s</translation>
    </message>
    <message>
        <source>Warning:</source>
        <translation>警告：</translation>
    </message>
</context>
<context>
    <name>footpath::SignalPlots</name>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>|a|</source>
        <translation>|a|</translation>
    </message>
    <message>
        <source>Pressure</source>
        <translation>气压</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>高度</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>加速度</translation>
    </message>
    <message>
        <source>Acceleration
(m/s²)</source>
        <translation>加速度
(m/s²)</translation>
    </message>
    <message>
        <source>Angular rate</source>
        <translation>角速度</translation>
    </message>
    <message>
        <source>Angular rate
(rad/s)</source>
        <translation>角速度
(rad/s)</translation>
    </message>
    <message>
        <source>Magnetic field</source>
        <translation>磁场</translation>
    </message>
    <message>
        <source>Magnetic field
(file units)</source>
        <translation>磁场
（文件单位）</translation>
    </message>
    <message>
        <source>Pressure
(hPa)</source>
        <translation>气压
(hPa)</translation>
    </message>
    <message>
        <source>Baro. height
(m)</source>
        <translation>气压高度
(m)</translation>
    </message>
    <message>
        <source>Channels</source>
        <translation>通道</translation>
    </message>
    <message>
        <source>Stance</source>
        <translation>支撑相</translation>
    </message>
    <message>
        <source>Show or hide this channel of the %1 row</source>
        <translation>显示或隐藏“%1”行中的此通道</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间 (s)</translation>
    </message>
</context>
<context>
    <name>footpath::StanceFlagsPlot</name>
    <message>
        <source>C1: |a| in range</source>
        <translation>C1: |a| 在范围内</translation>
    </message>
    <message>
        <source>C2: |a| steady</source>
        <translation>C2: |a| 平稳</translation>
    </message>
    <message>
        <source>C3: |ω| small</source>
        <translation>C3: |ω| 较小</translation>
    </message>
    <message>
        <source>C = C1·C2·C3</source>
        <translation>C = C1·C2·C3</translation>
    </message>
    <message>
        <source>Stance (median)</source>
        <translation>支撑相（中值）</translation>
    </message>
    <message>
        <source>|a|</source>
        <translation>|a|</translation>
    </message>
    <message>
        <source>|a|
(m/s²)</source>
        <translation>|a|
(m/s²)</translation>
    </message>
    <message>
        <source>std of |a|</source>
        <translation>|a| 的标准差</translation>
    </message>
    <message>
        <source>std of |a|
(m/s²)</source>
        <translation>|a| 标准差
(m/s²)</translation>
    </message>
    <message>
        <source>|ω|</source>
        <translation>|ω|</translation>
    </message>
    <message>
        <source>|ω|
(rad/s)</source>
        <translation>|ω|
(rad/s)</translation>
    </message>
    <message>
        <source>min |a| = %1 m/s²</source>
        <translation>最小 |a| = %1 m/s²</translation>
    </message>
    <message>
        <source>max |a| = %1 m/s²</source>
        <translation>最大 |a| = %1 m/s²</translation>
    </message>
    <message>
        <source>max std = %1 m/s²</source>
        <translation>最大标准差 = %1 m/s²</translation>
    </message>
    <message>
        <source>max |ω| = %1 rad/s</source>
        <translation>最大 |ω| = %1 rad/s</translation>
    </message>
    <message>
        <source>Detector</source>
        <translation>检测器</translation>
    </message>
    <message>
        <source>Show detector inputs</source>
        <translation>显示检测器输入</translation>
    </message>
    <message>
        <source>Plot |a|, its local standard deviation and |ω| with the detector&apos;s thresholds</source>
        <translation>绘制 |a|、其局部标准差和 |ω|，以及检测器的阈值</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <source>C: statistic
&lt; threshold</source>
        <translation>C：统计量
&lt; 阈值</translation>
    </message>
    <message>
        <source>Stance</source>
        <translation>支撑相</translation>
    </message>
    <message>
        <source>SHOE
statistic</source>
        <translation>SHOE
统计量</translation>
    </message>
    <message>
        <source>ARED
statistic</source>
        <translation>ARED
统计量</translation>
    </message>
    <message>
        <source>AMVD
statistic</source>
        <translation>AMVD
统计量</translation>
    </message>
    <message>
        <source>MBGTD
statistic</source>
        <translation>MBGTD
统计量</translation>
    </message>
    <message>
        <source>The inputs of the C1/C2/C3 detector; the chosen detector decides on its statistic, shown below the lanes</source>
        <translation>C1/C2/C3 检测器的输入；当前检测器依据其统计量判断，统计量显示在各通道下方</translation>
    </message>
    <message>
        <source>threshold (adaptive)</source>
        <translation>阈值（自适应）</translation>
    </message>
    <message>
        <source>threshold = 10^%1</source>
        <translation>阈值 = 10^%1</translation>
    </message>
</context>
<context>
    <name>footpath::SummaryPanel</name>
    <message>
        <source>Step</source>
        <translation>步序</translation>
    </message>
    <message>
        <source>Start (s)</source>
        <translation>开始 (s)</translation>
    </message>
    <message>
        <source>End (s)</source>
        <translation>结束 (s)</translation>
    </message>
    <message>
        <source>Stance (s)</source>
        <translation>支撑相 (s)</translation>
    </message>
    <message>
        <source>Stride (m)</source>
        <translation>步幅 (m)</translation>
    </message>
    <message>
        <source>Stride time (s)</source>
        <translation>跨步时长 (s)</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>z (m)</source>
        <translation>z (m)</translation>
    </message>
    <message>
        <source>When the foot came to rest</source>
        <translation>足部静止的时刻</translation>
    </message>
    <message>
        <source>When the foot lifted off</source>
        <translation>足部离地的时刻</translation>
    </message>
    <message>
        <source>How long the foot was at rest</source>
        <translation>足部静止的时长</translation>
    </message>
    <message>
        <source>Horizontal distance from the previous stance</source>
        <translation>与上一支撑相的水平距离</translation>
    </message>
    <message>
        <source>Time from the previous stance start to this one</source>
        <translation>从上一支撑相开始到本支撑相开始的时间</translation>
    </message>
    <message>
        <source>Mean position during the stance, relative to the start</source>
        <translation>支撑相期间的平均位置（相对于起点）</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>各步</translation>
    </message>
    <message>
        <source>Per step</source>
        <translation>每步</translation>
    </message>
    <message>
        <source>Distributions</source>
        <translation>分布</translation>
    </message>
    <message>
        <source>Walk</source>
        <translation>行走</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>路径长度</translation>
    </message>
    <message>
        <source>Stance phases / strides</source>
        <translation>支撑相 / 跨步</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>时长</translation>
    </message>
    <message>
        <source>Cadence</source>
        <translation>步频</translation>
    </message>
    <message>
        <source>Stride length</source>
        <translation>步幅</translation>
    </message>
    <message>
        <source>Stride duration</source>
        <translation>跨步时长</translation>
    </message>
    <message>
        <source>Stance duration</source>
        <translation>支撑相时长</translation>
    </message>
    <message>
        <source>End to start</source>
        <translation>终点至起点</translation>
    </message>
    <message>
        <source>Against the reference</source>
        <translation>相对参考</translation>
    </message>
    <message>
        <source>ARMSE 2D</source>
        <translation>ARMSE 2D</translation>
    </message>
    <message>
        <source>ARMSE 3D</source>
        <translation>ARMSE 3D</translation>
    </message>
    <message>
        <source>Loop closure</source>
        <translation>闭合误差</translation>
    </message>
    <message>
        <source>Distance error</source>
        <translation>距离误差</translation>
    </message>
    <message>
        <source>Stance precision</source>
        <translation>支撑相精确率</translation>
    </message>
    <message>
        <source>Stance recall</source>
        <translation>支撑相召回率</translation>
    </message>
    <message>
        <source>Stance F1</source>
        <translation>支撑相 F1</translation>
    </message>
    <message>
        <source>Stance phases</source>
        <translation>支撑相数</translation>
    </message>
    <message>
        <source>000 steps/min (00.0 strides/min)</source>
        <translation>000 步/分钟（00.0 跨步/分钟）</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 steps/min (%2 strides/min)</source>
        <translation>%1 步/分钟（%2 跨步/分钟）</translation>
    </message>
    <message>
        <source>%1 ± %2 m</source>
        <translation>%1 ± %2 m</translation>
    </message>
    <message>
        <source>%1 s (median %2 s)</source>
        <translation>%1 s（中位数 %2 s）</translation>
    </message>
    <message>
        <source>%1 m (%2 % of the path)</source>
        <translation>%1 m（路径的 %2 %）</translation>
    </message>
    <message>
        <source>%1 m (%2 % of %3 m)</source>
        <translation>%1 m（%3 m 的 %2 %）</translation>
    </message>
    <message>
        <source>%1 detected, %2 labelled</source>
        <translation>检测到 %1 个，标注 %2 个</translation>
    </message>
    <message>
        <source>Stride length per step</source>
        <translation>每步的步幅</translation>
    </message>
    <message>
        <source>Stride length (m)</source>
        <translation>步幅 (m)</translation>
    </message>
    <message>
        <source>Stance duration per step</source>
        <translation>每步的支撑相时长</translation>
    </message>
    <message>
        <source>Stance duration (s)</source>
        <translation>支撑相时长 (s)</translation>
    </message>
    <message>
        <source>Grey bars: %1 values below and %2 above the regular bins (outliers such as the standing still at the start and end)</source>
        <translation>灰色柱：%1 个值低于、%2 个值高于常规区间（离群值，例如开始和结束时的静止站立）</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>数量</translation>
    </message>
    <message>
        <source>No plausibility warnings</source>
        <translation>无合理性警告</translation>
    </message>
    <message numerus="yes">
        <source>%n plausibility warning(s)</source>
        <translation>
            <numerusform>%n 条合理性警告</numerusform>
        </translation>
    </message>
    <message>
        <source>Click the time span to move the time cursor there</source>
        <translation>点击时间段可将时间光标移至该处</translation>
    </message>
</context>
<context>
    <name>footpath::TrajectoryView2D</name>
    <message>
        <source>Reference</source>
        <translation>参考</translation>
    </message>
    <message>
        <source>Foot path</source>
        <translation>足部轨迹</translation>
    </message>
    <message>
        <source>Stance</source>
        <translation>支撑相</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>起点</translation>
    </message>
    <message>
        <source>End</source>
        <translation>终点</translation>
    </message>
    <message>
        <source>Time cursor</source>
        <translation>时间游标</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <source>foot speed (m/s)</source>
        <translation>足部速度 (m/s)</translation>
    </message>
</context>
<context>
    <name>footpath::TrajectoryView3D</name>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Vertical exaggeration: heights are drawn this many times larger</source>
        <translation>垂直夸大：高度按此倍数放大绘制</translation>
    </message>
    <message>
        <source>Height ×</source>
        <translation>高度 ×</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>透视</translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation>重置视图</translation>
    </message>
    <message>
        <source>Oblique view of the whole path (or double-click the view)</source>
        <translation>整条路径的斜视图（或双击视图）</translation>
    </message>
    <message>
        <source>No trajectory</source>
        <translation>无轨迹</translation>
    </message>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>Foot path</source>
        <translation>足部轨迹</translation>
    </message>
    <message>
        <source>Shadow on the floor</source>
        <translation>地面投影</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>参考</translation>
    </message>
    <message>
        <source>Stance</source>
        <translation>支撑相</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>起点</translation>
    </message>
    <message>
        <source>End</source>
        <translation>终点</translation>
    </message>
    <message>
        <source>Time cursor</source>
        <translation>时间游标</translation>
    </message>
    <message>
        <source>Heights drawn × %1</source>
        <translation>高度放大 × %1</translation>
    </message>
</context>
<context>
    <name>footpath::WarningOverlay</name>
    <message>
        <source>no initial rest</source>
        <translation>起始无静止</translation>
    </message>
    <message>
        <source>missed stance</source>
        <translation>漏检支撑相</translation>
    </message>
    <message>
        <source>stride too long</source>
        <translation>步幅过长</translation>
    </message>
    <message>
        <source>stride too slow</source>
        <translation>步幅过慢</translation>
    </message>
    <message>
        <source>stance share</source>
        <translation>支撑相占比</translation>
    </message>
    <message>
        <source>foot too fast</source>
        <translation>足速过快</translation>
    </message>
    <message>
        <source>few stances</source>
        <translation>支撑相过少</translation>
    </message>
    <message>
        <source>%1–%2 s</source>
        <translation>%1–%2 s</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Foot-mounted inertial navigation</source>
        <translation>足部安装式惯性导航</translation>
    </message>
    <message>
        <source>Recording to open</source>
        <translation>要打开的记录</translation>
    </message>
    <message>
        <source>Save a PNG of the window once estimated, then quit</source>
        <translation>估计完成后保存窗口的 PNG 截图，然后退出</translation>
    </message>
    <message>
        <source>Language (en, de, zh_CN)</source>
        <translation>语言（en、de、zh_CN）</translation>
    </message>
    <message>
        <source>Connect the live input to this serial port or emulator link</source>
        <translation>将实时输入连接到此串口或模拟器链接</translation>
    </message>
    <message>
        <source>--set expects name=value, got &apos;%1&apos;</source>
        <translation>--set 需要 name=value 形式，收到的是 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Start with the parameters of this preset (JSON)</source>
        <translation>以此预设（JSON）中的参数启动</translation>
    </message>
    <message>
        <source>Set one parameter, as footpath-cli does (repeatable)</source>
        <translation>设置一个参数，用法同 footpath-cli（可重复）</translation>
    </message>
    <message>
        <source>Show this view: signals, detector, trajectory2d or trajectory3d</source>
        <translation>显示此视图：signals、detector、trajectory2d 或 trajectory3d</translation>
    </message>
    <message>
        <source>Parameters from the command line</source>
        <translation>来自命令行的参数</translation>
    </message>
    <message>
        <source>Open the method comparison and run these sets, e.g. &quot;zupt;zupt,zaru;feliz&quot;</source>
        <translation>打开方法比较并运行这些组合，例如 &quot;zupt;zupt,zaru;feliz&quot;</translation>
    </message>
</context>
<context>
    <name>footpath::ComparisonPanel</name>
    <message>
        <source>Method sets to compare; tick the ones to run</source>
        <translation>要比较的方法组合；勾选要运行的组合</translation>
    </message>
    <message>
        <source>Add a set, e.g. zupt,hdr,mag</source>
        <translation>添加组合，例如 zupt,hdr,mag</translation>
    </message>
    <message>
        <source>Methods separated by commas: zupt, zaru, hdr, iper, zuna, baro, mag, feliz, 9state, 15state. Enter adds the set.</source>
        <translation>用逗号分隔的方法：zupt、zaru、hdr、iper、zuna、baro、mag、feliz、9state、15state。按回车添加。</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Run every ticked set on the current recording</source>
        <translation>在当前记录上运行所有勾选的组合</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Click a row to make its methods the workspace&apos;s parameters (Edit &gt; Undo goes back)</source>
        <translation>单击某行，将其方法设为工作区参数（编辑 &gt; 撤销可恢复）</translation>
    </message>
    <message>
        <source>Use as main result</source>
        <translation>用作主结果</translation>
    </message>
    <message>
        <source>Make the selected set&apos;s methods the workspace&apos;s parameters</source>
        <translation>将所选组合的方法设为工作区参数</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <source>height z (m)</source>
        <translation>高度 z (m)</translation>
    </message>
    <message>
        <source>Tick at least one method set.</source>
        <translation>请至少勾选一个方法组合。</translation>
    </message>
    <message>
        <source>best</source>
        <translation>最佳</translation>
    </message>
    <message>
        <source>Stale: the parameters changed since this comparison. Run again to update it.</source>
        <translation>已过时：自此次比较后参数已更改。请重新运行以更新。</translation>
    </message>
    <message>
        <source>Open a recording to compare methods on it.</source>
        <translation>打开一个记录以在其上比较方法。</translation>
    </message>
    <message>
        <source>Tick the sets and press Run.</source>
        <translation>勾选组合并点击运行。</translation>
    </message>
    <message>
        <source>Click a row to use its methods.</source>
        <translation>单击某行以使用其方法。</translation>
    </message>
    <message numerus="yes">
        <source>Running %n set(s)...</source>
        <translation>
            <numerusform>正在运行 %n 个组合...</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>footpath::ComparisonTable</name>
    <message>
        <source>failed: %1</source>
        <translation>失败：%1</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>no estimate</source>
        <translation>无估计结果</translation>
    </message>
    <message>
        <source>Method set</source>
        <translation>方法组合</translation>
    </message>
    <message>
        <source>End to start
(m)</source>
        <translation>终点到起点
(m)</translation>
    </message>
    <message>
        <source>End to start
(%)</source>
        <translation>终点到起点
(%)</translation>
    </message>
    <message>
        <source>Path length
(m)</source>
        <translation>路径长度
(m)</translation>
    </message>
    <message>
        <source>Height change
(m)</source>
        <translation>高度变化
(m)</translation>
    </message>
    <message>
        <source>ARMSE 2D
(m)</source>
        <translation>ARMSE 2D
(m)</translation>
    </message>
    <message>
        <source>Stance F1</source>
        <translation>支撑相 F1</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>步数</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
</context>
</TS>
