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
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Strides (turning)</source>
        <translation>跨步（转弯）</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>Stride time</source>
        <translation>跨步时长</translation>
    </message>
    <message>
        <source>Stride length</source>
        <translation>步幅</translation>
    </message>
    <message>
        <source>Cadence</source>
        <translation>步频</translation>
    </message>
    <message>
        <source>Stance / swing</source>
        <translation>支撑相 / 摆动相</translation>
    </message>
    <message>
        <source>%1 % / %2 %</source>
        <translation>%1 % / %2 %</translation>
    </message>
    <message>
        <source>Foot clearance</source>
        <translation>足部离地高度</translation>
    </message>
    <message>
        <source>Double support (both feet on the ground)</source>
        <translation>双支撑（双足着地）</translation>
    </message>
    <message>
        <source>%1 % of the gait cycle (initial %2 %, terminal %3 %), %4 strides</source>
        <translation>步态周期的 %1 %（初始 %2 %，末期 %3 %），%4 个跨步</translation>
    </message>
    <message>
        <source>Stance left / right</source>
        <translation>左 / 右支撑相</translation>
    </message>
    <message>
        <source>Symmetry index: stride time</source>
        <translation>对称指数：跨步时长</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Symmetry index: stride length</source>
        <translation>对称指数：步幅</translation>
    </message>
    <message>
        <source>Symmetry index: stance</source>
        <translation>对称指数：支撑相</translation>
    </message>
    <message>
        <source>Symmetry index: swing</source>
        <translation>对称指数：摆动相</translation>
    </message>
    <message>
        <source>Gait (heel strike to toe off)</source>
        <translation>步态（足跟着地至足尖离地）</translation>
    </message>
    <message>
        <source>From the gait events of %1: means over the strides that neither turn (more than 20 degrees) nor pause.</source>
        <translation>由%1的步态事件得出：对既不转弯（超过 20 度）也不停顿的跨步取平均。</translation>
    </message>
    <message>
        <source>the left foot</source>
        <translation>左脚</translation>
    </message>
    <message>
        <source>this foot</source>
        <translation>此脚</translation>
    </message>
    <message>
        <source>Both feet</source>
        <translation>双脚</translation>
    </message>
    <message>
        <source>The left and the right foot&apos;s files on one clock (their own time stamps). Symmetry index: 100 (left - right) / mean, 0 symmetric, positive where the left value is larger.</source>
        <translation>左脚和右脚的文件使用同一时钟（各自的时间戳）。对称指数：100 (左 - 右) / 平均值，0 表示对称，左侧数值较大时为正。</translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <source>Figure 9. Gait stance (heel strike to toe off, left) and foot clearance (right) per stride.</source>
        <translation>图 9. 每个跨步的步态支撑相（足跟着地至足尖离地，左）和足部离地高度（右）。</translation>
    </message>
    <message>
        <source>stride</source>
        <translation>跨步</translation>
    </message>
    <message>
        <source>stance (% of the stride)</source>
        <translation>支撑相（占跨步的 %）</translation>
    </message>
    <message>
        <source>clearance (m)</source>
        <translation>离地高度 (m)</translation>
    </message>
    <message>
        <source>Parameters (* and bold: differs from the default)</source>
        <translation>参数（* 和粗体：与默认值不同）</translation>
    </message>
    <message>
        <source>Figure 1. The foot path seen from above (reference dashed when present; the stances are too close together at this scale to be marked).</source>
        <translation>图 1. 俯视的足部轨迹（如有参考轨迹，以虚线表示；在此比例下支撑相过于密集，未予标出）。</translation>
    </message>
    <message>
        <source>Figure 3. The path in 3D (stance positions as dots; reference dashed when present).</source>
        <translation>图 3. 三维路径（支撑相位置以圆点表示；如有参考轨迹，以虚线表示）。</translation>
    </message>
    <message>
        <source>Figure 3. The path in 3D (reference dashed when present; the stances are too close together at this scale to be marked).</source>
        <translation>图 3. 三维路径（如有参考轨迹，以虚线表示；在此比例下支撑相过于密集，未予标出）。</translation>
    </message>
    <message>
        <source>%1 (%2 movements without a swing, under %3 m or %4 rad/s, merged into their stances)</source>
        <translation>%1（%2 次无摆动相的移动，小于 %3 m 或低于 %4 rad/s，已并入其支撑相）</translation>
    </message>
    <message>
        <source>Gait stance (heel strike to toe off) against the labels: precision / recall / F1</source>
        <translation>步态支撑相（足跟着地至足尖离地）相对标注：精确率 / 召回率 / F1</translation>
    </message>
    <message>
        <source>Strides in the labelled trial</source>
        <translation>已标注试验段内的跨步</translation>
    </message>
    <message>
        <source>%1 detected, %2 labelled swings</source>
        <translation>检测到 %1 个，标注的摆动相 %2 个</translation>
    </message>
    <message>
        <source>Foot at rest (ZUPT) against the labelled stance: precision / recall / F1 (the foot rests only mid-stance: a low recall is expected)</source>
        <translation>足部静止（ZUPT）相对标注支撑相：精确率 / 召回率 / F1（足部仅在支撑相中段静止：召回率偏低属预期）</translation>
    </message>
    <message>
        <source>Method comparison (stale)</source>
        <translation>方法比较（已过时）</translation>
    </message>
    <message>
        <source>Stale: the parameters changed after this comparison ran, so its rows were estimated with other parameters than the rest of this report. Run the comparison again to update it.</source>
        <translation>已过时：此次比较运行之后参数已更改，因此其各行所用的参数与本报告其余部分不同。请重新运行比较以更新。</translation>
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
    <message>
        <source>Methods separated by commas: %1. Enter adds the set.</source>
        <translation>用逗号分隔的方法：%1。按回车添加。</translation>
    </message>
</context>
<context>
    <name>footpath::HelpDialog</name>
    <message>
        <source>Footpath help</source>
        <translation>Footpath 帮助</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>用户指南</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <source>Click</source>
        <translation>单击</translation>
    </message>
    <message>
        <source>Plots and 2D path: move the time cursor there</source>
        <translation>曲线图和 2D 路径：将时间游标移到该处</translation>
    </message>
    <message>
        <source>Wheel</source>
        <translation>滚轮</translation>
    </message>
    <message>
        <source>Plots: zoom the time axis; 3D: zoom about the pointer</source>
        <translation>曲线图：缩放时间轴；3D：围绕指针缩放</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>拖动</translation>
    </message>
    <message>
        <source>Plots and 2D path: pan; 3D: orbit (right or middle button: pan)</source>
        <translation>曲线图和 2D 路径：平移；3D：旋转（右键或中键：平移）</translation>
    </message>
    <message>
        <source>Ctrl+Wheel</source>
        <translation>Ctrl+滚轮</translation>
    </message>
    <message>
        <source>Plots: zoom the value axis of the row under the pointer</source>
        <translation>曲线图：缩放指针下方那一行的数值轴</translation>
    </message>
    <message>
        <source>Wheel or drag on a value axis</source>
        <translation>在数值轴上滚动滚轮或拖动</translation>
    </message>
    <message>
        <source>Plots: zoom or pan that row&apos;s values</source>
        <translation>曲线图：缩放或平移该行的数值</translation>
    </message>
    <message>
        <source>Pointer over a plot</source>
        <translation>指针悬停在曲线图上</translation>
    </message>
    <message>
        <source>Plots and 2D path: read the time and the values there</source>
        <translation>曲线图和 2D 路径：读取该处的时间和数值</translation>
    </message>
    <message>
        <source>Shift+Click</source>
        <translation>Shift+单击</translation>
    </message>
    <message>
        <source>Plots and 2D path: set a marker; the readout then gives Δt and Δy from it</source>
        <translation>曲线图和 2D 路径：设置标记；读数随后给出相对它的 Δt 和 Δy</translation>
    </message>
    <message>
        <source>Right-click</source>
        <translation>右键单击</translation>
    </message>
    <message>
        <source>Plots: reset the view, export as PNG, SVG or PDF, or the visible data as CSV</source>
        <translation>曲线图：重置视图，导出为 PNG、SVG 或 PDF，或将可见数据导出为 CSV</translation>
    </message>
    <message>
        <source>Double-click</source>
        <translation>双击</translation>
    </message>
    <message>
        <source>Plots and paths: show everything again</source>
        <translation>曲线图和路径：重新显示全部</translation>
    </message>
    <message>
        <source>Up / Down</source>
        <translation>上 / 下</translation>
    </message>
    <message>
        <source>Parameter value field: one slider step</source>
        <translation>参数数值框：滑块移动一步</translation>
    </message>
    <message>
        <source>Page Up / Page Down</source>
        <translation>Page Up / Page Down</translation>
    </message>
    <message>
        <source>Parameter value field: ten slider steps</source>
        <translation>参数数值框：滑块移动十步</translation>
    </message>
    <message>
        <source>Step table: the next step, with the time cursor</source>
        <translation>步态表：下一步，时间游标随之移动</translation>
    </message>
    <message>
        <source>Keys or mouse</source>
        <translation>按键或鼠标</translation>
    </message>
    <message>
        <source>Does</source>
        <translation>作用</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Footpath in five minutes&lt;/h2&gt;&lt;p&gt;Footpath turns the recording of an inertial sensor on a shoe into the path walked: it finds the moments the foot rests on the ground (stance), integrates the motion in between, and corrects the drift with zero-velocity updates in a Kalman filter.&lt;/p&gt;&lt;h3&gt;Opening a recording&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;File &amp;gt; Open recording&lt;/b&gt;, the Recorded input panel, or drag a file onto the window. Xsens text exports, MT binary logs (.mtb), PyShoe CSV files and plain CSV/text with one sample per row are read.&lt;/li&gt;&lt;li&gt;A file that does not name its columns opens the import dialog: say which column holds what and in which unit; the dialog shows the first rows as they will be read.&lt;/li&gt;&lt;li&gt;The recording should start with about a second of standing still: the sensor&apos;s attitude is found from it.&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;What the views show&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Trajectory 2D / 3D&lt;/b&gt;: the path from above and in space. Orange dots are the stances, the green square is the start and the red cross the end, the yellow dot the time cursor; a dashed line is the reference when the file has one. After a parameter change the path before it stays as a faint grey ghost until the next change.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Signals&lt;/b&gt;: accelerometer, gyroscope and the other channels over time. The coloured lanes under them mark the stance phases (the foot at rest), plausibility warnings (red spans: a stride too long, a stance missed) and, with a barometer, the motion class of each step (level, stairs, elevator).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Stance detector&lt;/b&gt;: the statistic the detector thresholds and the threshold itself; where the curve is below the threshold the foot is taken to be at rest. A &lt;i&gt;Reference stance&lt;/i&gt; lane shows the stances the file&apos;s own labels give (gait events, motion capture), to compare with.&lt;/li&gt;&lt;li&gt;&lt;b&gt;States&lt;/b&gt;: the filter&apos;s attitude, velocity, height and sensor biases over time, with a band of one standard deviation where the filter estimates it.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Summary&lt;/b&gt;: the walk&apos;s figures (path length, strides, cadence, end-to-start distance), the figures against the reference when there is one, and a table of the steps. Selecting a step moves the time cursor to it in every view.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;One time cursor links every view: click a plot or the path and all views show that moment. Hold the pointer over a plot to read the values; Shift+click sets a marker to measure time and value differences from; right-click a plot to export it. &lt;b&gt;Help &amp;gt; Keyboard shortcuts&lt;/b&gt; lists every key.&lt;/p&gt;&lt;h3&gt;Tuning&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;The &lt;b&gt;Parameters&lt;/b&gt; panel lists every setting with its unit; the tool tip names the identifier used in presets and on the command line. A setting that has no effect with the others is greyed out, and its tool tip says why.&lt;/li&gt;&lt;li&gt;Every change re-estimates at once. The summary then shows the key figures before and after the change, green where the change helped and red where it hurt, and the &lt;b&gt;History&lt;/b&gt; lists the last runs: double-click one to go back to it. Undo (Ctrl+Z) goes back one change.&lt;/li&gt;&lt;li&gt;Presets save and load the whole set; &lt;b&gt;Analysis &amp;gt; Compare methods&lt;/b&gt; runs several method sets on the same recording side by side.&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;Live input&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;In the &lt;b&gt;Live input&lt;/b&gt; panel choose the sensor&apos;s serial port (or the emulator) and connect: the live path and signals appear in their own tabs while you walk.&lt;/li&gt;&lt;li&gt;Record writes the samples to a file (the name offered is the device&apos;s and the time&apos;s, in the folder of the last recording); when recording stops, the file opens for the full analysis. A session you did not record can still be saved after Disconnect.&lt;/li&gt;&lt;li&gt;A recording that starts while walking is still read: the path then starts at the first stance, and a warning says so.&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;Exporting&lt;/h3&gt;&lt;p&gt;&lt;b&gt;File &amp;gt; Export report&lt;/b&gt; writes a PDF with the figures, plots and parameters; &lt;b&gt;Export CSV&lt;/b&gt; writes the trajectory, steps, summary and parameters as CSV files.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;五分钟上手 Footpath&lt;/h2&gt;&lt;p&gt;Footpath 将鞋上惯性传感器的记录转换为行走的路径：它找出足部静止在地面上的时刻（支撑相），对其间的运动进行积分，并在卡尔曼滤波器中用零速更新校正漂移。&lt;/p&gt;&lt;h3&gt;打开记录&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;文件 &amp;gt; 打开记录&lt;/b&gt;、“记录输入”面板，或将文件拖到窗口上。可读取 Xsens 文本导出、MT 二进制日志 (.mtb)、PyShoe CSV 文件，以及每行一个采样的普通 CSV/文本文件。&lt;/li&gt;&lt;li&gt;未标明列名的文件会打开导入对话框：请指定每列的内容及其单位；对话框会按读取方式显示前几行。&lt;/li&gt;&lt;li&gt;记录开始时应静止站立约一秒：传感器的姿态由此确定。&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;各视图显示的内容&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;2D / 3D 轨迹&lt;/b&gt;：俯视和空间中的路径。橙色圆点为支撑相，绿色方块为起点，红色叉号为终点，黄色圆点为时间游标；若文件含参考轨迹，则以虚线表示。参数更改后，更改前的路径会以淡灰色的残影保留，直到下一次更改。&lt;/li&gt;&lt;li&gt;&lt;b&gt;信号&lt;/b&gt;：加速度计、陀螺仪及其他通道随时间的变化。其下方的彩色条带标出支撑相（足部静止）、合理性警告（红色时段：步幅过长、漏检支撑相），以及有气压计时每一步的运动类别（平地、楼梯、电梯）。&lt;/li&gt;&lt;li&gt;&lt;b&gt;支撑相检测器&lt;/b&gt;：检测器用于阈值比较的统计量及阈值本身；曲线低于阈值处，足部被视为静止。&lt;i&gt;参考支撑相&lt;/i&gt;条带显示文件自带标注（步态事件、动作捕捉）给出的支撑相，以供比较。&lt;/li&gt;&lt;li&gt;&lt;b&gt;状态&lt;/b&gt;：滤波器估计的姿态、速度、高度和传感器零偏随时间的变化，在滤波器估计标准差之处附有一个标准差的带。&lt;/li&gt;&lt;li&gt;&lt;b&gt;摘要&lt;/b&gt;：行走的指标（路径长度、跨步、步频、终点到起点的距离）、如有参考则给出相对参考的指标，以及各步的表格。选中某一步会将所有视图中的时间游标移到该步。&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;一个时间游标联动所有视图：单击曲线图或路径，所有视图都会显示该时刻。将指针悬停在曲线图上可读取数值；Shift+单击设置标记，用于测量相对它的时间差和数值差；右键单击曲线图可将其导出。&lt;b&gt;帮助 &amp;gt; 键盘快捷键&lt;/b&gt;列出所有按键。&lt;/p&gt;&lt;h3&gt;调参&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;参数&lt;/b&gt;面板列出每个设置及其单位；工具提示给出预设和命令行中使用的标识符。与其他设置组合时不起作用的设置会显示为灰色，其工具提示会说明原因。&lt;/li&gt;&lt;li&gt;每次更改都会立即重新估计。摘要随后显示更改前后的关键指标，改善处为绿色，变差处为红色；&lt;b&gt;历史&lt;/b&gt;列出最近几次运行：双击其中一次即可回到该次。撤销 (Ctrl+Z) 回退一次更改。&lt;/li&gt;&lt;li&gt;预设可保存和加载整套参数；&lt;b&gt;分析 &amp;gt; 比较方法&lt;/b&gt;可在同一记录上并排运行多个方法组合。&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;实时输入&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;在&lt;b&gt;实时输入&lt;/b&gt;面板中选择传感器的串口（或模拟器）并连接：行走时，实时路径和信号会显示在各自的标签页中。&lt;/li&gt;&lt;li&gt;“记录”将采样写入文件（建议的文件名由设备名和时间组成，位于上次记录所在的文件夹）；记录停止后，该文件会打开以进行完整分析。未记录的会话在断开连接后仍可保存。&lt;/li&gt;&lt;li&gt;在行走中开始的记录仍可读取：此时路径从第一个支撑相开始，并会给出相应警告。&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;导出&lt;/h3&gt;&lt;p&gt;&lt;b&gt;文件 &amp;gt; 导出报告&lt;/b&gt;生成包含指标、曲线图和参数的 PDF；&lt;b&gt;导出 CSV&lt;/b&gt;将轨迹、各步、摘要和参数写入 CSV 文件。&lt;/p&gt;</translation>
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
    <message>
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>%1 needs import settings and no one is there to give them: %2</source>
        <translation>%1 需要导入设置，但无人提供：%2</translation>
    </message>
    <message>
        <source>What each column holds (the first lines of the file below, numbered as in the file):</source>
        <translation>各列的内容（下方为文件的前几行，行号与文件中一致）：</translation>
    </message>
    <message>
        <source>column %1</source>
        <translation>第 %1 列</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>第 %1 行</translation>
    </message>
    <message>
        <source>Line %1 is the file&apos;s header: its names title the columns, and the roles below replace it.</source>
        <translation>第 %1 行是文件的表头：其名称用作列标题，下方的用途设置将取代它。</translation>
    </message>
    <message>
        <source>The file has no header row: say what each column holds.</source>
        <translation>文件没有表头行：请指定每列的内容。</translation>
    </message>
    <message>
        <source>Cannot be right: %1</source>
        <translation>不可能正确：%1</translation>
    </message>
    <message>
        <source>Check: %1</source>
        <translation>请检查：%1</translation>
    </message>
    <message>
        <source>Read so, the first lines give: %1</source>
        <translation>按此读取，前几行得到：%1</translation>
    </message>
    <message>
        <source>From the values: %1</source>
        <translation>根据数值：%1</translation>
    </message>
    <message>
        <source>Mend the roles or units first: the file cannot be read right so</source>
        <translation>请先修正用途或单位：按当前设置无法正确读取该文件</translation>
    </message>
</context>
<context>
    <name>footpath::LivePanel</name>
    <message>
        <source>A serial port, or type a path such as the emulator&apos;s pseudo-terminal</source>
        <translation>串口，或输入路径，例如模拟器的伪终端</translation>
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
    <message>
        <source>Refresh the list of ports</source>
        <translation>刷新端口列表</translation>
    </message>
    <message>
        <source>Save...</source>
        <translation>保存...</translation>
    </message>
    <message>
        <source>Save the samples received in the last session (kept in memory) as a CSV file and open it as a recorded walk: for a session that was not recorded</source>
        <translation>将上次会话中接收的采样（保存在内存中）另存为 CSV 文件，并作为已记录的行走打开：适用于未记录的会话</translation>
    </message>
    <message>
        <source>Horizontal distance from the start to where the foot is now</source>
        <translation>从起点到足部当前位置的水平距离</translation>
    </message>
    <message>
        <source>Duration:</source>
        <translation>时长：</translation>
    </message>
    <message>
        <source>End to start:</source>
        <translation>终点到起点：</translation>
    </message>
    <message>
        <source>Warnings:</source>
        <translation>警告：</translation>
    </message>
    <message>
        <source>Live session: %1</source>
        <translation>实时会话：%1</translation>
    </message>
    <message>
        <source>Samples saved to %1</source>
        <translation>采样已保存到 %1</translation>
    </message>
    <message>
        <source>Save samples</source>
        <translation>保存采样</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Unsaved samples</source>
        <translation>未保存的采样</translation>
    </message>
    <message>
        <source>The last session&apos;s %1 samples were not recorded. Save them before connecting again?</source>
        <translation>上次会话的 %1 个采样尚未记录。是否在重新连接前保存？</translation>
    </message>
    <message>
        <source>Not connected: choose a port and Connect (Live input panel)</source>
        <translation>未连接：请选择端口并点击连接（实时输入面板）</translation>
    </message>
    <message>
        <source>Not connected: %1</source>
        <translation>未连接：%1</translation>
    </message>
    <message>
        <source>Connecting to %1...</source>
        <translation>正在连接到 %1...</translation>
    </message>
    <message>
        <source>Connected: waiting for samples...</source>
        <translation>已连接：正在等待采样...</translation>
    </message>
    <message>
        <source>Disconnected: the session failed</source>
        <translation>已断开：会话失败</translation>
    </message>
    <message>
        <source>The connection failed.</source>
        <translation>连接失败。</translation>
    </message>
    <message>
        <source>Aligning: keep the foot still for %1 s (a walk already under way is aligned at its first stance)</source>
        <translation>对准中：请保持足部静止 %1 s（已在行走中的会话将在其第一个支撑相对准）</translation>
    </message>
    <message>
        <source>Estimating (%1 s behind)</source>
        <translation>正在估计（滞后 %1 s）</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>Live: %1 steps, %2 m, %3 s, end to start %4 m, warnings: %5</source>
        <translation>实时：%1 步，%2 m，%3 s，终点到起点 %4 m，警告：%5</translation>
    </message>
    <message>
        <source>Samples the views could not keep up with (the window was busy for longer than the display queue holds). They are in the recording all the same.</source>
        <translation>视图未能及时显示的样本（窗口繁忙的时间超过了显示队列的容量）。它们仍完整保存在记录中。</translation>
    </message>
    <message>
        <source>Not shown:</source>
        <translation>未显示：</translation>
    </message>
    <message>
        <source>Re-estimating with the new parameters (the old estimate is shown meanwhile)</source>
        <translation>正在用新参数重新估计（期间显示旧的估计）</translation>
    </message>
    <message>
        <source>The %1 samples received before the port went away were not recorded. Reconnecting starts a new session without them. Save them before reconnecting?</source>
        <translation>端口消失前接收的 %1 个采样尚未记录。重新连接将开始一个不含这些采样的新会话。是否在重新连接前保存？</translation>
    </message>
    <message>
        <source>The live session&apos;s %1 samples were not recorded. Save them before quitting?</source>
        <translation>实时会话的 %1 个采样尚未记录。是否在退出前保存？</translation>
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
        <source>live</source>
        <translation>实时</translation>
    </message>
    <message>
        <source>The live session&apos;s path seen from above, as it grows</source>
        <translation>实时会话的俯视路径，随行走逐步延伸</translation>
    </message>
    <message>
        <source>The live session&apos;s path in three dimensions, as it grows</source>
        <translation>实时会话的三维路径，随行走逐步延伸</translation>
    </message>
    <message>
        <source>Live IMU</source>
        <translation>实时 IMU</translation>
    </message>
    <message>
        <source>Live signals: the live session&apos;s last seconds of sensor signals</source>
        <translation>实时信号：实时会话最近几秒的传感器信号</translation>
    </message>
    <message>
        <source>Live stance</source>
        <translation>实时支撑相</translation>
    </message>
    <message>
        <source>Live stance detector: the live session&apos;s detector over its last seconds</source>
        <translation>实时支撑相检测器：实时会话最近几秒的检测器</translation>
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
    <message>
        <source>IMU</source>
        <translation>IMU</translation>
    </message>
    <message>
        <source>Signals: the recorded walk&apos;s sensor signals</source>
        <translation>信号：已记录行走的传感器信号</translation>
    </message>
    <message>
        <source>Stance</source>
        <translation>支撑相</translation>
    </message>
    <message>
        <source>Stance detector: the recorded walk&apos;s statistics, thresholds, lanes</source>
        <translation>支撑相检测器：已记录行走的统计量、阈值和条带</translation>
    </message>
    <message>
        <source>States</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>States: the recorded walk&apos;s attitude, velocity, biases</source>
        <translation>状态：已记录行走的姿态、速度和零偏</translation>
    </message>
    <message>
        <source>2D</source>
        <translation>2D</translation>
    </message>
    <message>
        <source>Trajectory 2D: the recorded walk&apos;s path seen from above</source>
        <translation>2D 轨迹：俯视的已记录行走路径</translation>
    </message>
    <message>
        <source>3D</source>
        <translation>3D</translation>
    </message>
    <message>
        <source>Trajectory 3D: the recorded walk&apos;s path in three dimensions</source>
        <translation>3D 轨迹：已记录行走的三维路径</translation>
    </message>
    <message>
        <source>History</source>
        <translation>历史</translation>
    </message>
    <message>
        <source>&amp;User guide</source>
        <translation>用户指南(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <source>Undo the last change</source>
        <translation>撤销上一次更改</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <source>S&amp;tates</source>
        <translation>状态(&amp;T)</translation>
    </message>
    <message>
        <source>Back to run %1</source>
        <translation>回到第 %1 次运行</translation>
    </message>
    <message>
        <source>Left foot</source>
        <translation>左脚</translation>
    </message>
    <message>
        <source>&amp;Tune for this recording...</source>
        <translation>为此记录调参(&amp;T)...</translation>
    </message>
    <message>
        <source>Search the detector settings and the filter noise that fit this recording best</source>
        <translation>搜索最适合此记录的检测器设置和滤波器噪声</translation>
    </message>
    <message>
        <source>Tune over a &amp;folder...</source>
        <translation>对文件夹调参(&amp;F)...</translation>
    </message>
    <message>
        <source>One parameter set for many recordings of a sensor and a way of walking</source>
        <translation>为同一传感器和同一行走方式的多个记录找出一套参数</translation>
    </message>
    <message>
        <source>Tune for this recording</source>
        <translation>为此记录调参</translation>
    </message>
    <message>
        <source>Open a recording first.</source>
        <translation>请先打开一个记录。</translation>
    </message>
    <message>
        <source>Right foot</source>
        <translation>右脚</translation>
    </message>
    <message>
        <source>Open recording (two files: both feet)</source>
        <translation>打开记录（两个文件：双脚）</translation>
    </message>
    <message>
        <source>%1 files: open one recording, or the left and the right file of one walk</source>
        <translation>%1 个文件：请打开一个记录，或同一次行走的左脚和右脚文件</translation>
    </message>
    <message>
        <source>Footpath - %1 + %2</source>
        <translation>Footpath - %1 + %2</translation>
    </message>
    <message>
        <source>unknown view &apos;%1&apos;%2; the views are %3</source>
        <translation>未知视图 &apos;%1&apos;%2；可用的视图为 %3</translation>
    </message>
    <message>
        <source>Trajectory, steps and summary of both feet, and the parameters, written to %1</source>
        <translation>双脚的轨迹、各步和摘要以及参数已写入 %1</translation>
    </message>
    <message>
        <source>Recordings (%1);;All files (*)</source>
        <translation>记录 (%1);;所有文件 (*)</translation>
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
        <source>Colour each stride by its step&apos;s motion class (stairs, elevator); needs a barometer</source>
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
        <source>Counted from the barometer&apos;s height between steps (Zheng et al. 2016); a floor is 3 m</source>
        <translation>由步间气压高度统计（Zheng et al. 2016）；一层按 3 m 计</translation>
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
    <name>footpath::OtherFootSession</name>
    <message>
        <source>%1 (the right foot): %2</source>
        <translation>%1（右脚）：%2</translation>
    </message>
    <message>
        <source>The right foot&apos;s estimate failed: %1</source>
        <translation>右脚估计失败：%1</translation>
    </message>
</context>
<context>
    <name>footpath::ParameterFields</name>
    <message>
        <source>Alignment period</source>
        <translation>对准时长</translation>
    </message>
    <message>
        <source>Static period at the start used for alignment</source>
        <translation>开始时用于对准的静止时段</translation>
    </message>
    <message>
        <source>Alignment</source>
        <translation>对准</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>重力加速度</translation>
    </message>
    <message>
        <source>Local gravity</source>
        <translation>当地重力加速度</translation>
    </message>
    <message>
        <source>Magnetic declination</source>
        <translation>磁偏角</translation>
    </message>
    <message>
        <source>Magnetic declination subtracted from the compass heading</source>
        <translation>从罗盘航向中减去的磁偏角</translation>
    </message>
    <message>
        <source>Stance detector</source>
        <translation>支撑相检测器</translation>
    </message>
    <message>
        <source>C1/C2/C3 (Guo 2015)</source>
        <translation>C1/C2/C3（Guo 2015）</translation>
    </message>
    <message>
        <source>SHOE (GLRT)</source>
        <translation>SHOE（GLRT）</translation>
    </message>
    <message>
        <source>ARED (angular rate energy)</source>
        <translation>ARED（角速度能量）</translation>
    </message>
    <message>
        <source>AMVD (acceleration variance)</source>
        <translation>AMVD（加速度方差）</translation>
    </message>
    <message>
        <source>MBGTD (graph theoretic)</source>
        <translation>MBGTD（图论方法）</translation>
    </message>
    <message>
        <source>Statistic that decides the foot is at rest</source>
        <translation>判定足部静止的统计量</translation>
    </message>
    <message>
        <source>Detector</source>
        <translation>检测器</translation>
    </message>
    <message>
        <source>Statistic window</source>
        <translation>统计量窗口</translation>
    </message>
    <message>
        <source>Window of the detector statistic</source>
        <translation>检测器统计量的窗口</translation>
    </message>
    <message>
        <source>Accelerometer noise</source>
        <translation>加速度计噪声</translation>
    </message>
    <message>
        <source>Accelerometer noise the statistic is normalised by</source>
        <translation>用于归一化统计量的加速度计噪声</translation>
    </message>
    <message>
        <source>Gyroscope noise</source>
        <translation>陀螺仪噪声</translation>
    </message>
    <message>
        <source>Gyroscope noise the statistic is normalised by</source>
        <translation>用于归一化统计量的陀螺仪噪声</translation>
    </message>
    <message>
        <source>Adaptive threshold</source>
        <translation>自适应阈值</translation>
    </message>
    <message>
        <source>Threshold follows the motion (off: a fixed threshold)</source>
        <translation>阈值随运动调整（关闭：固定阈值）</translation>
    </message>
    <message>
        <source>Fixed threshold</source>
        <translation>固定阈值</translation>
    </message>
    <message>
        <source>Fixed threshold on the statistic (log10), when not adaptive</source>
        <translation>非自适应时统计量的固定阈值（log10）</translation>
    </message>
    <message>
        <source>Adaptive window</source>
        <translation>自适应窗口</translation>
    </message>
    <message>
        <source>Adaptive: window of the running minimum (about one gait cycle)</source>
        <translation>自适应：滑动最小值的窗口（约一个步态周期）</translation>
    </message>
    <message>
        <source>Offset above the minimum</source>
        <translation>高于最小值的偏移</translation>
    </message>
    <message>
        <source>Adaptive: threshold above the running minimum</source>
        <translation>自适应：阈值高出滑动最小值的量</translation>
    </message>
    <message>
        <source>Fraction towards the maximum</source>
        <translation>趋向最大值的比例</translation>
    </message>
    <message>
        <source>Adaptive: threshold this fraction of the way from the running minimum to the maximum</source>
        <translation>自适应：阈值位于从滑动最小值到最大值之间的这一比例处</translation>
    </message>
    <message>
        <source>Always at rest below</source>
        <translation>低于此值始终静止</translation>
    </message>
    <message>
        <source>Adaptive: below this the foot is always at rest</source>
        <translation>自适应：低于此值时足部始终视为静止</translation>
    </message>
    <message>
        <source>Never at rest above</source>
        <translation>高于此值从不静止</translation>
    </message>
    <message>
        <source>Adaptive: above this the foot is never at rest</source>
        <translation>自适应：高于此值时足部从不视为静止</translation>
    </message>
    <message>
        <source>Shortest stance</source>
        <translation>最短支撑相</translation>
    </message>
    <message>
        <source>Shorter stance runs are dropped</source>
        <translation>更短的支撑相段将被舍弃</translation>
    </message>
    <message>
        <source>C1 lower bound on |a|</source>
        <translation>C1 |a| 下限</translation>
    </message>
    <message>
        <source>C1: lower bound on |a|</source>
        <translation>C1：|a| 的下限</translation>
    </message>
    <message>
        <source>C1 upper bound on |a|</source>
        <translation>C1 |a| 上限</translation>
    </message>
    <message>
        <source>C1: upper bound on |a|</source>
        <translation>C1：|a| 的上限</translation>
    </message>
    <message>
        <source>C2 bound on the std of |a|</source>
        <translation>C2 |a| 标准差上限</translation>
    </message>
    <message>
        <source>C2: std of |a| over the window must be below</source>
        <translation>C2：窗口内 |a| 的标准差须低于此值</translation>
    </message>
    <message>
        <source>C2 half-window</source>
        <translation>C2 半窗口</translation>
    </message>
    <message>
        <source>C2: half-window of the centred std</source>
        <translation>C2：中心化标准差的半窗口</translation>
    </message>
    <message>
        <source>C3 bound on |ω|</source>
        <translation>C3 |ω| 上限</translation>
    </message>
    <message>
        <source>C3: upper bound on |w|</source>
        <translation>C3：|w| 的上限</translation>
    </message>
    <message>
        <source>Median filter length</source>
        <translation>中值滤波长度</translation>
    </message>
    <message>
        <source>Median filter length applied to C</source>
        <translation>作用于 C 的中值滤波长度</translation>
    </message>
    <message>
        <source>Filter states</source>
        <translation>滤波器状态</translation>
    </message>
    <message>
        <source>15 states (with biases)</source>
        <translation>15 状态（含零偏）</translation>
    </message>
    <message>
        <source>9 states (no bias states)</source>
        <translation>9 状态（无零偏状态）</translation>
    </message>
    <message>
        <source>Error-state filter size: 15 estimates the sensor biases, 9 holds them at zero</source>
        <translation>误差状态滤波器的维数：15 状态估计传感器零偏，9 状态将其固定为零</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>滤波器</translation>
    </message>
    <message>
        <source>Estimator</source>
        <translation>估计器</translation>
    </message>
    <message>
        <source>Kalman filter</source>
        <translation>卡尔曼滤波器</translation>
    </message>
    <message>
        <source>Feliz de-drift (no filter)</source>
        <translation>Feliz 去漂移（无滤波器）</translation>
    </message>
    <message>
        <source>Kalman filter + RTS smoother</source>
        <translation>卡尔曼滤波器 + RTS 平滑器</translation>
    </message>
    <message>
        <source>Kalman filter with the measurements below, Feliz 2009&apos;s per-stride velocity de-drift, or the filter followed by a Rauch-Tung-Striebel smoother over the whole recording (offline; live input runs the filter)</source>
        <translation>使用下列观测的卡尔曼滤波器、Feliz 2009 的逐跨步速度去漂移，或滤波器之后再对整个记录做 Rauch-Tung-Striebel 平滑（离线；实时输入只运行滤波器）</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>观测</translation>
    </message>
    <message>
        <source>Zero-velocity update (ZUPT)</source>
        <translation>零速更新（ZUPT）</translation>
    </message>
    <message>
        <source>Zero-velocity update during stance</source>
        <translation>支撑相期间的零速更新</translation>
    </message>
    <message>
        <source>Zero angular rate update (ZARU)</source>
        <translation>零角速度更新（ZARU）</translation>
    </message>
    <message>
        <source>Zero angular rate update during stance</source>
        <translation>支撑相期间的零角速度更新</translation>
    </message>
    <message>
        <source>Heuristic drift reduction (HDR)</source>
        <translation>启发式漂移抑制（HDR）</translation>
    </message>
    <message>
        <source>Heuristic drift reduction: heading held on straight walks</source>
        <translation>启发式漂移抑制：直线行走时保持航向</translation>
    </message>
    <message>
        <source>Position error reduction (IPER)</source>
        <translation>位置误差抑制（IPER）</translation>
    </message>
    <message>
        <source>Position error reduction: walks along the building&apos;s axes, level floor (assumes a rectilinear building)</source>
        <translation>位置误差抑制：沿建筑轴线行走、楼面水平（假定建筑为直角布局）</translation>
    </message>
    <message>
        <source>Zero navigation acceleration (ZUNA)</source>
        <translation>零导航加速度（ZUNA）</translation>
    </message>
    <message>
        <source>Zero navigation acceleration at mid-stance</source>
        <translation>支撑相中段的零导航加速度</translation>
    </message>
    <message>
        <source>Barometric height</source>
        <translation>气压高度</translation>
    </message>
    <message>
        <source>Barometric height at each stance (Zheng et al. 2016)</source>
        <translation>每个支撑相的气压高度（Zheng et al. 2016）</translation>
    </message>
    <message>
        <source>Magnetometer heading</source>
        <translation>磁力计航向</translation>
    </message>
    <message>
        <source>Magnetometer heading during stance, skipped near steel</source>
        <translation>支撑相期间的磁力计航向，靠近钢材时跳过</translation>
    </message>
    <message>
        <source>HDR heading lag</source>
        <translation>HDR 航向滞后</translation>
    </message>
    <message>
        <source>HDR: heading compared with the heading this long ago</source>
        <translation>HDR：将航向与这段时间之前的航向比较</translation>
    </message>
    <message>
        <source>HDR</source>
        <translation>HDR</translation>
    </message>
    <message>
        <source>HDR turn threshold</source>
        <translation>HDR 转弯阈值</translation>
    </message>
    <message>
        <source>HDR: a smaller heading change is drift, a larger one a turn</source>
        <translation>HDR：较小的航向变化视为漂移，较大的视为转弯</translation>
    </message>
    <message>
        <source>HDR measurement std</source>
        <translation>HDR 观测标准差</translation>
    </message>
    <message>
        <source>HDR: R of the heading measurement, std</source>
        <translation>HDR：航向观测的 R，标准差</translation>
    </message>
    <message>
        <source>Building axis from the walk</source>
        <translation>由行走确定建筑轴线</translation>
    </message>
    <message>
        <source>IPER: building axis from the walk&apos;s dominant directions</source>
        <translation>IPER：由行走的主方向确定建筑轴线</translation>
    </message>
    <message>
        <source>IPER</source>
        <translation>IPER</translation>
    </message>
    <message>
        <source>Building axis angle</source>
        <translation>建筑轴线角度</translation>
    </message>
    <message>
        <source>IPER: angle of the building&apos;s main axis from x</source>
        <translation>IPER：建筑主轴相对 x 轴的角度</translation>
    </message>
    <message>
        <source>Along-axis tolerance</source>
        <translation>沿轴容差</translation>
    </message>
    <message>
        <source>IPER: walking within this of an axis counts as along it</source>
        <translation>IPER：行走方向与某轴线的偏差在此范围内即视为沿该轴行走</translation>
    </message>
    <message>
        <source>IPER window</source>
        <translation>IPER 窗口</translation>
    </message>
    <message>
        <source>IPER: displacement window</source>
        <translation>IPER：位移窗口</translation>
    </message>
    <message>
        <source>IPER cross-axis std</source>
        <translation>IPER 横向标准差</translation>
    </message>
    <message>
        <source>IPER: R of the cross-axis displacement, std</source>
        <translation>IPER：垂直于轴线方向位移的 R，标准差</translation>
    </message>
    <message>
        <source>IPER level-floor height std</source>
        <translation>IPER 水平楼面高度标准差</translation>
    </message>
    <message>
        <source>IPER: R of the level-floor height, std</source>
        <translation>IPER：水平楼面高度的 R，标准差</translation>
    </message>
    <message>
        <source>ZUNA reference period</source>
        <translation>ZUNA 参考时长</translation>
    </message>
    <message>
        <source>ZUNA: static start averaged for the reference</source>
        <translation>ZUNA：对开始时的静止段取平均作为参考</translation>
    </message>
    <message>
        <source>ZUNA</source>
        <translation>ZUNA</translation>
    </message>
    <message>
        <source>ZUNA shortest stance</source>
        <translation>ZUNA 最短支撑相</translation>
    </message>
    <message>
        <source>ZUNA: mid-stance needs a stance run this long</source>
        <translation>ZUNA：支撑相须持续这么长才取其中段</translation>
    </message>
    <message>
        <source>ZUNA margin below the threshold</source>
        <translation>ZUNA 低于阈值的裕量</translation>
    </message>
    <message>
        <source>ZUNA: mid-stance statistic this far below the threshold</source>
        <translation>ZUNA：支撑相中段的统计量须低于阈值这么多</translation>
    </message>
    <message>
        <source>ZUNA measurement std</source>
        <translation>ZUNA 观测标准差</translation>
    </message>
    <message>
        <source>ZUNA: R of the acceleration, std</source>
        <translation>ZUNA：加速度的 R，标准差</translation>
    </message>
    <message>
        <source>Pressure to height</source>
        <translation>气压转高度</translation>
    </message>
    <message>
        <source>Barometric formula</source>
        <translation>气压公式</translation>
    </message>
    <message>
        <source>Linear constant (Zheng et al. 2016)</source>
        <translation>线性常数（Zheng et al. 2016）</translation>
    </message>
    <message>
        <source>Barometer: pressure difference to height</source>
        <translation>气压计：由气压差换算高度</translation>
    </message>
    <message>
        <source>Barometer</source>
        <translation>气压计</translation>
    </message>
    <message>
        <source>Linear constant N</source>
        <translation>线性常数 N</translation>
    </message>
    <message>
        <source>Barometer: linear constant N</source>
        <translation>气压计：线性常数 N</translation>
    </message>
    <message>
        <source>Barometer height std</source>
        <translation>气压计高度标准差</translation>
    </message>
    <message>
        <source>Barometer: R of the height, std</source>
        <translation>气压计：高度的 R，标准差</translation>
    </message>
    <message>
        <source>Level walking height change</source>
        <translation>平地行走高度变化</translation>
    </message>
    <message>
        <source>Motion class: smaller height change per step is level walking</source>
        <translation>运动类别：每步高度变化小于此值即为平地行走</translation>
    </message>
    <message>
        <source>Elevator pressure variance</source>
        <translation>电梯气压方差</translation>
    </message>
    <message>
        <source>Motion class: pressure variance between steps above this is an elevator</source>
        <translation>运动类别：步间气压方差高于此值即为电梯</translation>
    </message>
    <message>
        <source>Magnetometer heading std</source>
        <translation>磁力计航向标准差</translation>
    </message>
    <message>
        <source>Magnetometer: R of the heading, std</source>
        <translation>磁力计：航向的 R，标准差</translation>
    </message>
    <message>
        <source>Magnetometer</source>
        <translation>磁力计</translation>
    </message>
    <message>
        <source>Field strength tolerance</source>
        <translation>场强容差</translation>
    </message>
    <message>
        <source>Magnetometer: |m| within this fraction of its value at alignment</source>
        <translation>磁力计：|m| 与对准时的值相差在此比例以内</translation>
    </message>
    <message>
        <source>Dip angle tolerance</source>
        <translation>磁倾角容差</translation>
    </message>
    <message>
        <source>Magnetometer: dip within this of its value at alignment</source>
        <translation>磁力计：磁倾角与对准时的值相差在此范围以内</translation>
    </message>
    <message>
        <source>Q attitude</source>
        <translation>Q 姿态</translation>
    </message>
    <message>
        <source>Q attitude, std per 10 ms</source>
        <translation>Q 姿态，每 10 ms 的标准差</translation>
    </message>
    <message>
        <source>Process noise</source>
        <translation>过程噪声</translation>
    </message>
    <message>
        <source>Q gyroscope bias</source>
        <translation>Q 陀螺仪零偏</translation>
    </message>
    <message>
        <source>Q gyro bias, std per 10 ms</source>
        <translation>Q 陀螺零偏，每 10 ms 的标准差</translation>
    </message>
    <message>
        <source>Q position</source>
        <translation>Q 位置</translation>
    </message>
    <message>
        <source>Q position, std per 10 ms</source>
        <translation>Q 位置，每 10 ms 的标准差</translation>
    </message>
    <message>
        <source>Q velocity</source>
        <translation>Q 速度</translation>
    </message>
    <message>
        <source>Q velocity, std per 10 ms</source>
        <translation>Q 速度，每 10 ms 的标准差</translation>
    </message>
    <message>
        <source>Q accelerometer bias</source>
        <translation>Q 加速度计零偏</translation>
    </message>
    <message>
        <source>Q accelerometer bias, std per 10 ms</source>
        <translation>Q 加速度计零偏，每 10 ms 的标准差</translation>
    </message>
    <message>
        <source>R zero velocity</source>
        <translation>R 零速</translation>
    </message>
    <message>
        <source>R ZUPT, std</source>
        <translation>R ZUPT，标准差</translation>
    </message>
    <message>
        <source>Measurement noise</source>
        <translation>观测噪声</translation>
    </message>
    <message>
        <source>R zero angular rate</source>
        <translation>R 零角速度</translation>
    </message>
    <message>
        <source>R ZARU, std</source>
        <translation>R ZARU，标准差</translation>
    </message>
    <message>
        <source>P0 attitude</source>
        <translation>P0 姿态</translation>
    </message>
    <message>
        <source>P0 attitude, std</source>
        <translation>P0 姿态，标准差</translation>
    </message>
    <message>
        <source>Initial covariance</source>
        <translation>初始协方差</translation>
    </message>
    <message>
        <source>P0 gyroscope bias</source>
        <translation>P0 陀螺仪零偏</translation>
    </message>
    <message>
        <source>P0 gyro bias, std</source>
        <translation>P0 陀螺零偏，标准差</translation>
    </message>
    <message>
        <source>P0 position</source>
        <translation>P0 位置</translation>
    </message>
    <message>
        <source>P0 position, std</source>
        <translation>P0 位置，标准差</translation>
    </message>
    <message>
        <source>P0 velocity</source>
        <translation>P0 速度</translation>
    </message>
    <message>
        <source>P0 velocity, std</source>
        <translation>P0 速度，标准差</translation>
    </message>
    <message>
        <source>P0 accelerometer bias</source>
        <translation>P0 加速度计零偏</translation>
    </message>
    <message>
        <source>P0 accelerometer bias, std</source>
        <translation>P0 加速度计零偏，标准差</translation>
    </message>
    <message>
        <source>Innovation gate</source>
        <translation>新息门限</translation>
    </message>
    <message>
        <source>Aiding measurements (HDR, IPER, ZUNA, barometer, magnetometer) less likely than this under the filter&apos;s own uncertainty are rejected (chi-square test); 0: no gate. ZUPT and ZARU are never gated.</source>
        <translation>在滤波器自身不确定性下比此概率更不可能的辅助测量（HDR、IPER、ZUNA、气压计、磁力计）将被拒绝（卡方检验）；0：不设门限。ZUPT 和 ZARU 从不检验。</translation>
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
    <message>
        <source>%1&lt;br&gt;Choices in presets: %2&lt;br&gt;Default: %3</source>
        <translation>%1&lt;br&gt;预设中的可选值：%2&lt;br&gt;默认值：%3</translation>
    </message>
    <message>
        <source>Not used: HDR is off (use_hdr).</source>
        <translation>未使用：HDR 已关闭（use_hdr）。</translation>
    </message>
    <message>
        <source>Not used: IPER is off (use_iper).</source>
        <translation>未使用：IPER 已关闭（use_iper）。</translation>
    </message>
    <message>
        <source>Not used: the axis is estimated from the walk (iper_axis_auto is on).</source>
        <translation>未使用：轴由行走数据估计（iper_axis_auto 已开启）。</translation>
    </message>
    <message>
        <source>Not used: ZUNA is off (use_zuna).</source>
        <translation>未使用：ZUNA 已关闭（use_zuna）。</translation>
    </message>
    <message>
        <source>Not used: the barometer is off (use_baro).</source>
        <translation>未使用：气压计已关闭（use_baro）。</translation>
    </message>
    <message>
        <source>Not used: the barometric formula is chosen, not the linear constant.</source>
        <translation>未使用：当前选择的是气压公式，而非线性常数。</translation>
    </message>
    <message>
        <source>Not used: the magnetometer heading update is off (use_mag_heading).</source>
        <translation>未使用：磁力计航向更新已关闭（use_mag_heading）。</translation>
    </message>
    <message>
        <source> (the slider up to %1; type a larger value)</source>
        <translation>（滑块最大至 %1；更大的值请直接输入）</translation>
    </message>
    <message>
        <source>%1&lt;br&gt;Range: %2 to %3 %4%6&lt;br&gt;Default: %5 %4&lt;br&gt;Up/Down in the value field: one slider step; Page Up/Down: ten</source>
        <translation>%1&lt;br&gt;范围：%2 至 %3 %4%6&lt;br&gt;默认值：%5 %4&lt;br&gt;数值框中的上/下键：滑块移动一步；Page Up/Down：十步</translation>
    </message>
</context>
<context>
    <name>footpath::PlotInteraction</name>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>   Δt = %1 s from the marker</source>
        <translation>   相对标记 Δt = %1 s</translation>
    </message>
    <message>
        <source> (Δ %1)</source>
        <translation> (Δ %1)</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>无法写入 %1。</translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation>重置视图</translation>
    </message>
    <message>
        <source>Clear measurement marker</source>
        <translation>清除测量标记</translation>
    </message>
    <message>
        <source>Shift+click sets the marker; the readout then shows the differences to it</source>
        <translation>Shift+单击设置标记；读数随后显示相对它的差值</translation>
    </message>
    <message>
        <source>Export as PNG…</source>
        <translation>导出为 PNG…</translation>
    </message>
    <message>
        <source>Export plot as PNG</source>
        <translation>将曲线图导出为 PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <source>Export as SVG…</source>
        <translation>导出为 SVG…</translation>
    </message>
    <message>
        <source>Export plot as SVG</source>
        <translation>将曲线图导出为 SVG</translation>
    </message>
    <message>
        <source>SVG images (*.svg)</source>
        <translation>SVG 图像 (*.svg)</translation>
    </message>
    <message>
        <source>Export as PDF (vector)…</source>
        <translation>导出为 PDF（矢量）…</translation>
    </message>
    <message>
        <source>Export plot as PDF</source>
        <translation>将曲线图导出为 PDF</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <source>Export visible data as CSV…</source>
        <translation>将可见数据导出为 CSV…</translation>
    </message>
    <message>
        <source>Export visible data as CSV</source>
        <translation>将可见数据导出为 CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
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
    <message>
        <source>&lt;p&gt;&lt;b&gt;Left foot&lt;/b&gt;&lt;/p&gt;%1&lt;hr&gt;&lt;p&gt;&lt;b&gt;Right foot&lt;/b&gt;&lt;/p&gt;%2</source>
        <translation>&lt;p&gt;&lt;b&gt;左脚&lt;/b&gt;&lt;/p&gt;%1&lt;hr&gt;&lt;p&gt;&lt;b&gt;右脚&lt;/b&gt;&lt;/p&gt;%2</translation>
    </message>
</context>
<context>
    <name>footpath::RunHistory</name>
    <message>
        <source>First run</source>
        <translation>首次运行</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message numerus="yes">
        <source>%1; %2 and %n more</source>
        <translation>
            <numerusform>%1；%2 及另外 %n 项</numerusform>
        </translation>
    </message>
    <message>
        <source>No change</source>
        <translation>无更改</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Change</source>
        <translation>更改</translation>
    </message>
    <message>
        <source>Path (m)</source>
        <translation>路径 (m)</translation>
    </message>
    <message>
        <source>End to start (m)</source>
        <translation>终点到起点 (m)</translation>
    </message>
    <message>
        <source>ARMSE 2D (m)</source>
        <translation>ARMSE 2D (m)</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>步数</translation>
    </message>
    <message>
        <source>Back to run %1: %2</source>
        <translation>回到第 %1 次运行：%2</translation>
    </message>
</context>
<context>
    <name>footpath::RunHistoryPanel</name>
    <message>
        <source>Go back to this run</source>
        <translation>回到此次运行</translation>
    </message>
    <message>
        <source>The last %1 estimates of this recording (bold: the one shown). Double-click one to go back to its parameters; Undo goes back too.</source>
        <translation>此记录最近 %1 次估计（粗体：当前显示的一次）。双击某次即可回到其参数；撤销也可回退。</translation>
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
    <message>
        <source>Heel strike</source>
        <translation>足跟着地</translation>
    </message>
    <message>
        <source>Toe off</source>
        <translation>足尖离地</translation>
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
    <message>
        <source>stance</source>
        <translation>支撑相</translation>
    </message>
    <message>
        <source>swing</source>
        <translation>摆动相</translation>
    </message>
    <message>
        <source>1 (set)</source>
        <translation>1（置位）</translation>
    </message>
    <message>
        <source>0</source>
        <translation>0</translation>
    </message>
    <message>
        <source>Reference
stance</source>
        <translation>参考
支撑相</translation>
    </message>
    <message>
        <source>Reference stance</source>
        <translation>参考支撑相</translation>
    </message>
    <message>
        <source>from the recording&apos;s reference stance column (zero velocity by motion capture)</source>
        <translation>来自记录中的参考支撑相列（由动作捕捉得到的零速）</translation>
    </message>
    <message>
        <source>between the hand-labelled gait events (toe-off, heel-strike)</source>
        <translation>位于人工标注的步态事件（足尖离地、足跟着地）之间</translation>
    </message>
    <message>
        <source>%1
statistic</source>
        <translation>%1
统计量</translation>
    </message>
</context>
<context>
    <name>footpath::StatePlots</name>
    <message>
        <source>Attitude
(°)</source>
        <translation>姿态
(°)</translation>
    </message>
    <message>
        <source>roll</source>
        <translation>横滚</translation>
    </message>
    <message>
        <source>pitch</source>
        <translation>俯仰</translation>
    </message>
    <message>
        <source>yaw</source>
        <translation>偏航</translation>
    </message>
    <message>
        <source>Velocity
(m/s)</source>
        <translation>速度
(m/s)</translation>
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
        <source>Height
(m)</source>
        <translation>高度
(m)</translation>
    </message>
    <message>
        <source>height</source>
        <translation>高度</translation>
    </message>
    <message>
        <source>Gyro bias
(rad/s)</source>
        <translation>陀螺零偏
(rad/s)</translation>
    </message>
    <message>
        <source>Acc. bias
(m/s²)</source>
        <translation>加计零偏
(m/s²)</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <source>±1σ</source>
        <translation>±1σ</translation>
    </message>
    <message>
        <source>σ %1</source>
        <translation>σ %1</translation>
    </message>
    <message>
        <source>Not estimated (constant)</source>
        <translation>未估计（常数）</translation>
    </message>
    <message>
        <source>No ±1σ band: this estimator keeps no covariance</source>
        <translation>无 ±1σ 带：此估计器不保留协方差</translation>
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
    <message>
        <source>Heel strike (s)</source>
        <translation>足跟着地 (s)</translation>
    </message>
    <message>
        <source>Toe off (s)</source>
        <translation>足尖离地 (s)</translation>
    </message>
    <message>
        <source>Gait stance (%)</source>
        <translation>步态支撑相 (%)</translation>
    </message>
    <message>
        <source>Clearance (m)</source>
        <translation>离地高度 (m)</translation>
    </message>
    <message>
        <source>The gait stride whose stance holds this step: when the foot landed</source>
        <translation>其支撑相包含此步的步态跨步：足部着地的时刻</translation>
    </message>
    <message>
        <source>When the foot left the ground (the end of the gait lab&apos;s stance)</source>
        <translation>足部离开地面的时刻（步态实验室意义上支撑相的结束）</translation>
    </message>
    <message>
        <source>Heel strike to toe off, % of the stride time</source>
        <translation>足跟着地至足尖离地，占跨步时长的 %</translation>
    </message>
    <message>
        <source>Highest point of the swing after this stance above it</source>
        <translation>此支撑相之后摆动相的最高点，相对该支撑相的高度</translation>
    </message>
    <message>
        <source>Gait</source>
        <translation>步态</translation>
    </message>
    <message>
        <source>Gait (heel strike to toe off)</source>
        <translation>步态（足跟着地至足尖离地）</translation>
    </message>
    <message>
        <source>Strides</source>
        <translation>跨步</translation>
    </message>
    <message>
        <source>Stride time</source>
        <translation>跨步时长</translation>
    </message>
    <message>
        <source>Stance / swing</source>
        <translation>支撑相 / 摆动相</translation>
    </message>
    <message>
        <source>Foot clearance</source>
        <translation>足部离地高度</translation>
    </message>
    <message>
        <source>From the gait events (heel strike, toe off) of this foot: means over the strides that neither turn nor pause</source>
        <translation>由此脚的步态事件（足跟着地、足尖离地）得出：对既不转弯也不停顿的跨步取平均</translation>
    </message>
    <message>
        <source>Both feet</source>
        <translation>双脚</translation>
    </message>
    <message>
        <source>Double support</source>
        <translation>双支撑</translation>
    </message>
    <message>
        <source>Stance left / right</source>
        <translation>左 / 右支撑相</translation>
    </message>
    <message>
        <source>Symmetry: stride time</source>
        <translation>对称性：跨步时长</translation>
    </message>
    <message>
        <source>Symmetry: stride length</source>
        <translation>对称性：步幅</translation>
    </message>
    <message>
        <source>Symmetry: stance</source>
        <translation>对称性：支撑相</translation>
    </message>
    <message>
        <source>Symmetry: swing</source>
        <translation>对称性：摆动相</translation>
    </message>
    <message>
        <source>Double support: the share of the gait cycle both feet are on the ground. Symmetry index: 100 (left - right) / mean, 0 symmetric, positive: the left larger.</source>
        <translation>双支撑：双足同时着地的时间占步态周期的比例。对称指数：100 (左 - 右) / 平均值，0 表示对称，正值：左侧较大。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Live session&lt;/b&gt;: the figures of the estimate so far. The recorded walk&apos;s return when its views are shown again.</source>
        <translation>&lt;b&gt;实时会话&lt;/b&gt;：目前估计结果的指标。再次显示已记录行走的视图时，其指标会恢复。</translation>
    </message>
    <message>
        <source>Last change</source>
        <translation>上次更改</translation>
    </message>
    <message>
        <source>The figures before and after the last parameter change (the grey ghost path). Green: better, red: worse. The History lists every run.</source>
        <translation>上次参数更改前后的指标（灰色残影路径）。绿色：更好，红色：更差。历史列出每次运行。</translation>
    </message>
    <message>
        <source>%1 → %2 m</source>
        <translation>%1 → %2 m</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>%1 (%2 turning)</source>
        <translation>%1（转弯 %2）</translation>
    </message>
    <message>
        <source>%1 steps/min</source>
        <translation>%1 步/分钟</translation>
    </message>
    <message>
        <source>%1 % / %2 %</source>
        <translation>%1 % / %2 %</translation>
    </message>
    <message>
        <source>%1 % of the gait cycle (%2 strides)</source>
        <translation>步态周期的 %1 %（%2 个跨步）</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Gait stance per stride (heel strike to toe off)</source>
        <translation>每个跨步的步态支撑相（足跟着地至足尖离地）</translation>
    </message>
    <message>
        <source>Stance (% of the stride)</source>
        <translation>支撑相（占跨步的 %）</translation>
    </message>
    <message>
        <source>Stride</source>
        <translation>跨步</translation>
    </message>
    <message>
        <source>Foot clearance per stride</source>
        <translation>每个跨步的足部离地高度</translation>
    </message>
    <message>
        <source>Gait stance P / R / F1</source>
        <translation>步态支撑相 P / R / F1</translation>
    </message>
    <message>
        <source>Strides in the trial</source>
        <translation>试验段内的跨步</translation>
    </message>
    <message>
        <source>At rest (ZUPT) precision</source>
        <translation>静止（ZUPT）精确率</translation>
    </message>
    <message>
        <source>At rest (ZUPT) recall</source>
        <translation>静止（ZUPT）召回率</translation>
    </message>
    <message>
        <source>At rest (ZUPT) F1</source>
        <translation>静止（ZUPT）F1</translation>
    </message>
    <message>
        <source>The gait events&apos; stance (heel strike to toe off) against the labelled one, sample by sample: precision, recall and F1. This is the figure to compare with a gait lab&apos;s labels.</source>
        <translation>由步态事件得到的支撑相（足跟着地至足尖离地）与标注的支撑相逐采样点比较：精确率、召回率和 F1。与步态实验室的标注比较时应看这一指标。</translation>
    </message>
    <message>
        <source>The detector&apos;s foot at rest (the zero-velocity updates) against the labelled stance. The foot rests only in the middle of its stance, so the recall is low by design; the precision says no swing was taken for rest.</source>
        <translation>检测器判定的足部静止（即零速更新）与标注支撑相的比较。足部仅在支撑相中段静止，因此召回率按设计就偏低；精确率表明没有把摆动相误判为静止。</translation>
    </message>
    <message>
        <source>Strides whose swing lies inside the labelled trial, against the labelled swings there</source>
        <translation>摆动相位于已标注试验段内的跨步，与该段内标注的摆动相比较</translation>
    </message>
    <message>
        <source>Movements between stances that were no stride (under %1 m, or never turning at a swing&apos;s %2 rad/s: shifting the weight while standing), merged into one stance:</source>
        <translation>支撑相之间不构成跨步的移动（小于 %1 m，或角速度从未达到摆动相的 %2 rad/s：站立时转移重心），已合并为一个支撑相：</translation>
    </message>
    <message>
        <source>%1-%2 s: %3 m, at most %4 rad/s</source>
        <translation>%1-%2 s：%3 m，最大 %4 rad/s</translation>
    </message>
    <message>
        <source>... and %1 more</source>
        <translation>... 另有 %1 项</translation>
    </message>
    <message>
        <source>%1 / %2 (%3 merged: no swing)</source>
        <translation>%1 / %2（%3 个已合并：无摆动相）</translation>
    </message>
    <message>
        <source>%1 detected, %2 labelled swings</source>
        <translation>检测到 %1 个，标注的摆动相 %2 个</translation>
    </message>
    <message>
        <source>%1 / %2 / %3</source>
        <translation>%1 / %2 / %3</translation>
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
    <message>
        <source>x = %1 m   y = %2 m   t = %3 s</source>
        <translation>x = %1 m   y = %2 m   t = %3 s</translation>
    </message>
    <message>
        <source>
from the marker: Δt = %1 s   Δx = %2 m   Δy = %3 m   distance %4 m</source>
        <translation>
相对标记：Δt = %1 s   Δx = %2 m   Δy = %3 m   距离 %4 m</translation>
    </message>
    <message>
        <source>Before the last change</source>
        <translation>上次更改之前</translation>
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
    <message>
        <source>Before the last change</source>
        <translation>上次更改之前</translation>
    </message>
</context>
<context>
    <name>footpath::TuneCriterionChoice</name>
    <message>
        <source>Minimise</source>
        <translation>最小化</translation>
    </message>
</context>
<context>
    <name>footpath::TuneDialog</name>
    <message>
        <source>on</source>
        <translation>开</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message>
        <source>End-to-start distance of a closed walk (%)</source>
        <translation>闭合行走的终点到起点距离 (%)</translation>
    </message>
    <message>
        <source>Error of the path length (%)</source>
        <translation>路径长度误差 (%)</translation>
    </message>
    <message>
        <source>Position error against the reference (ARMSE, m)</source>
        <translation>相对参考的位置误差（ARMSE，m）</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>The criterion the search minimised</source>
        <translation>搜索所最小化的准则</translation>
    </message>
    <message>
        <source>Tune for %1</source>
        <translation>为 %1 调参</translation>
    </message>
    <message>
        <source>What is known about the walk</source>
        <translation>关于此次行走的已知信息</translation>
    </message>
    <message>
        <source>The walk ends where it started</source>
        <translation>行走的终点即起点</translation>
    </message>
    <message>
        <source>Then the distance from its end to its start is the error to minimise</source>
        <translation>此时终点到起点的距离即为要最小化的误差</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>The length of the walked path, if measured; then the error of the estimated length is the error to minimise</source>
        <translation>所走路径的长度（如已测量）；此时估计长度的误差即为要最小化的误差</translation>
    </message>
    <message>
        <source>Path length:</source>
        <translation>路径长度：</translation>
    </message>
    <message>
        <source>Parameter sets to try, the current one included; more finds better settings but takes longer</source>
        <translation>要尝试的参数组数，包括当前参数；越多越能找到更好的设置，但耗时更长</translation>
    </message>
    <message numerus="yes">
        <source>on %n core(s)</source>
        <translation>
            <numerusform>使用 %n 个核心</numerusform>
        </translation>
    </message>
    <message>
        <source>Evaluations:</source>
        <translation>评估次数：</translation>
    </message>
    <message>
        <source>%v of %m evaluations</source>
        <translation>%v / %m 次评估</translation>
    </message>
    <message>
        <source>What changed</source>
        <translation>变化内容</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>之前</translation>
    </message>
    <message>
        <source>After</source>
        <translation>之后</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Stop searching and keep the best parameters found so far</source>
        <translation>停止搜索并保留目前找到的最佳参数</translation>
    </message>
    <message>
        <source>Use the tuned parameters</source>
        <translation>使用调参后的参数</translation>
    </message>
    <message>
        <source>Make them the workspace&apos;s parameters (Edit &gt; Undo brings the current ones back)</source>
        <translation>将其设为工作区参数（编辑 &gt; 撤销可恢复当前参数）</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>no recording is open</source>
        <translation>未打开记录</translation>
    </message>
    <message>
        <source>needs a walk that ends where it started: tick it if yours does</source>
        <translation>需要终点即起点的行走：如果你的行走如此，请勾选</translation>
    </message>
    <message>
        <source>needs the path length: enter it</source>
        <translation>需要路径长度：请输入</translation>
    </message>
    <message>
        <source>needs reference positions: this recording has none</source>
        <translation>需要参考位置：此记录没有</translation>
    </message>
    <message>
        <source>Trying the current parameters, then a spread over the whole range...</source>
        <translation>正在尝试当前参数，然后在整个范围内散布尝试...</translation>
    </message>
    <message>
        <source>Stopping; the best parameters so far are kept...</source>
        <translation>正在停止；将保留目前最佳的参数...</translation>
    </message>
    <message>
        <source>Best so far: %1</source>
        <translation>目前最佳：%1</translation>
    </message>
    <message>
        <source>Searching around the best parameters found so far...</source>
        <translation>正在目前最佳参数附近搜索...</translation>
    </message>
    <message>
        <source>Best: %1</source>
        <translation>最佳：%1</translation>
    </message>
    <message numerus="yes">
        <source>Stopped after %n evaluation(s).</source>
        <translation>
            <numerusform>已在 %n 次评估后停止。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Done: %n evaluation(s).</source>
        <translation>
            <numerusform>完成：%n 次评估。</numerusform>
        </translation>
    </message>
    <message>
        <source>No better parameters were found; the current ones stay.</source>
        <translation>未找到更好的参数；保留当前参数。</translation>
    </message>
    <message>
        <source>The path with the tuned parameters, over the current one (orange). Use them, or keep the current ones.</source>
        <translation>调参后参数得到的路径，叠加在当前路径（橙色）之上。可使用新参数，或保留当前参数。</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>路径长度</translation>
    </message>
    <message>
        <source>The estimated path&apos;s length, for comparison</source>
        <translation>估计路径的长度，供比较</translation>
    </message>
    <message>
        <source>End to start</source>
        <translation>终点到起点</translation>
    </message>
    <message>
        <source>The distance from the path&apos;s end to its start, for comparison</source>
        <translation>路径终点到起点的距离，供比较</translation>
    </message>
    <message>
        <source>Beware: the tuned path is %1 % shorter than the current one; a smaller error may come from a path that shrank rather than from a better one.</source>
        <translation>注意：调参后的路径比当前路径短 %1 %；误差变小可能源于路径缩短，而非路径更好。</translation>
    </message>
    <message>
        <source>Beware: the tuned path is %1 % longer than the current one.</source>
        <translation>注意：调参后的路径比当前路径长 %1 %。</translation>
    </message>
    <message>
        <source>Current parameters</source>
        <translation>当前参数</translation>
    </message>
    <message>
        <source>Start again</source>
        <translation>重新开始</translation>
    </message>
    <message>
        <source>Keep the current ones</source>
        <translation>保留当前参数</translation>
    </message>
    <message>
        <source>Tuned parameters</source>
        <translation>调参后的参数</translation>
    </message>
    <message>
        <source>Beware: the tuned parameters change the strides, not only the figure (a swing split in two or a stance lost looks like this):</source>
        <translation>注意：调参后的参数改变的是跨步本身，而不仅是指标（摆动相被一分为二或丢失支撑相时就会如此）：</translation>
    </message>
</context>
<context>
    <name>footpath::TuneFolderDialog</name>
    <message>
        <source>%1: no samples</source>
        <translation>%1：无采样</translation>
    </message>
    <message>
        <source>Tune over a folder</source>
        <translation>对文件夹调参</translation>
    </message>
    <message>
        <source>Choose a folder of recordings of one sensor and one way of walking.</source>
        <translation>请选择一个文件夹，其中为同一传感器、同一行走方式的记录。</translation>
    </message>
    <message>
        <source>Choose...</source>
        <translation>选择...</translation>
    </message>
    <message>
        <source>Detect (headerless files: the usual columns)</source>
        <translation>自动检测（无表头文件：常用列）</translation>
    </message>
    <message>
        <source>How to read files that do not describe themselves</source>
        <translation>如何读取未自带说明的文件</translation>
    </message>
    <message>
        <source>Every walk ends where it started</source>
        <translation>每次行走的终点即起点</translation>
    </message>
    <message>
        <source>Score every recording by its end-to-start distance, also those not marked closed</source>
        <translation>按终点到起点的距离为每个记录评分，包括未标记为闭合的记录</translation>
    </message>
    <message>
        <source>Folder:</source>
        <translation>文件夹：</translation>
    </message>
    <message>
        <source>Read with:</source>
        <translation>读取方式：</translation>
    </message>
    <message>
        <source>Parameter sets to try, each on every recording</source>
        <translation>要尝试的参数组数，每组都在每个记录上运行</translation>
    </message>
    <message>
        <source>Evaluations:</source>
        <translation>评估次数：</translation>
    </message>
    <message numerus="yes">
        <source>on %n core(s)</source>
        <translation>
            <numerusform>使用 %n 个核心</numerusform>
        </translation>
    </message>
    <message>
        <source>%v of %m evaluations</source>
        <translation>%v / %m 次评估</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>记录</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>之前</translation>
    </message>
    <message>
        <source>After</source>
        <translation>之后</translation>
    </message>
    <message>
        <source>What changed</source>
        <translation>变化内容</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Stop searching and keep the best parameters found so far</source>
        <translation>停止搜索并保留目前找到的最佳参数</translation>
    </message>
    <message>
        <source>Save preset...</source>
        <translation>保存预设...</translation>
    </message>
    <message>
        <source>Apply to the workspace</source>
        <translation>应用到工作区</translation>
    </message>
    <message>
        <source>Make them the workspace&apos;s parameters (Edit &gt; Undo brings the current ones back)</source>
        <translation>将其设为工作区参数（编辑 &gt; 撤销可恢复当前参数）</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Folder of recordings</source>
        <translation>记录所在文件夹</translation>
    </message>
    <message>
        <source>Reading the recordings in %1...</source>
        <translation>正在读取 %1 中的记录...</translation>
    </message>
    <message>
        <source>No recording could be read in this folder.</source>
        <translation>此文件夹中没有可读取的记录。</translation>
    </message>
    <message numerus="yes">
        <source>%n recording(s) read. Choose what to minimise and start.</source>
        <translation>
            <numerusform>已读取 %n 个记录。请选择要最小化的量，然后开始。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Not read (%n file(s)):</source>
        <translation>
            <numerusform>未读取（%n 个文件）：</numerusform>
        </translation>
    </message>
    <message>
        <source>no recordings read yet</source>
        <translation>尚未读取任何记录</translation>
    </message>
    <message>
        <source>no walk is marked closed: tick it if they all end where they started</source>
        <translation>没有行走被标记为闭合：如果所有行走的终点都是起点，请勾选</translation>
    </message>
    <message>
        <source>no recording has a known length (e.g. walk_72m.txt, or a sidecar)</source>
        <translation>没有记录具有已知长度（例如 walk_72m.txt，或附带的说明文件）</translation>
    </message>
    <message>
        <source>no recording has reference positions</source>
        <translation>没有记录具有参考位置</translation>
    </message>
    <message>
        <source>None of the recordings has what this criterion needs.</source>
        <translation>没有任何记录具备此准则所需的数据。</translation>
    </message>
    <message numerus="yes">
        <source>Tuning on %n recording(s): the current parameters, then a spread over the whole range...</source>
        <translation>
            <numerusform>正在 %n 个记录上调参：先用当前参数，然后在整个范围内散布尝试...</numerusform>
        </translation>
    </message>
    <message>
        <source>Stopping; the best parameters so far are kept...</source>
        <translation>正在停止；将保留目前最佳的参数...</translation>
    </message>
    <message>
        <source>Best mean so far: %1</source>
        <translation>目前最佳平均值：%1</translation>
    </message>
    <message>
        <source>Searching around the best parameters found so far...</source>
        <translation>正在目前最佳参数附近搜索...</translation>
    </message>
    <message>
        <source>Best mean: %1</source>
        <translation>最佳平均值：%1</translation>
    </message>
    <message numerus="yes">
        <source>Stopped after %n evaluation(s).</source>
        <translation>
            <numerusform>已在 %n 次评估后停止。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Done: %n evaluation(s).</source>
        <translation>
            <numerusform>完成：%n 次评估。</numerusform>
        </translation>
    </message>
    <message>
        <source>No better parameters were found; the current ones stay.</source>
        <translation>未找到更好的参数；保留当前参数。</translation>
    </message>
    <message>
        <source>Save them as a preset, or apply them to the workspace.</source>
        <translation>可将其保存为预设，或应用到工作区。</translation>
    </message>
    <message>
        <source>Not scored: the recording lacks what the criterion needs</source>
        <translation>未评分：该记录缺少此准则所需的数据</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>平均值</translation>
    </message>
    <message>
        <source>Start again</source>
        <translation>重新开始</translation>
    </message>
    <message>
        <source>Save preset</source>
        <translation>保存预设</translation>
    </message>
    <message>
        <source>Presets (*.json)</source>
        <translation>预设 (*.json)</translation>
    </message>
    <message>
        <source>Preset written to %1</source>
        <translation>预设已写入 %1</translation>
    </message>
    <message>
        <source>Parameters tuned over %1</source>
        <translation>在 %1 上调参得到的参数</translation>
    </message>
    <message>
        <source>Beware: the tuned parameters change the strides, not only the figure: %1</source>
        <translation>注意：调参后的参数改变的是跨步本身，而不仅是指标：%1</translation>
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
        <source>height vs barometer</source>
        <translation>高度与气压计不符</translation>
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
        <source>Parameters from the command line</source>
        <translation>来自命令行的参数</translation>
    </message>
    <message>
        <source>Open the method comparison and run these sets, e.g. &quot;zupt;zupt,zaru;feliz&quot;</source>
        <translation>打开方法比较并运行这些组合，例如 &quot;zupt;zupt,zaru;feliz&quot;</translation>
    </message>
    <message>
        <source>Recording to open; two files (or a folder): the left and the right foot of one walk</source>
        <translation>要打开的记录；两个文件（或一个文件夹）：同一次行走的左脚和右脚</translation>
    </message>
    <message>
        <source>Show this view: signals, detector, states, trajectory2d, trajectory3d, motion, summary, steps or gait</source>
        <translation>显示此视图：signals、detector、states、trajectory2d、trajectory3d、motion、summary、steps 或 gait</translation>
    </message>
    <message>
        <source>Read the recording with this column map, as footpath-cli does (time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,...)</source>
        <translation>按此列映射读取记录，用法同 footpath-cli（time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,...）</translation>
    </message>
    <message>
        <source>Read the recording with a saved import preset</source>
        <translation>使用已保存的导入预设读取记录</translation>
    </message>
</context>
</TS>
