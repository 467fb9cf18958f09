<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>QObject</name>
    <message>
        <source>R %1  G %2  B %3 (sRGB %4, %5, %6)</source>
        <translation>R %1  G %2  B %3 (sRGB %4, %5, %6)</translation>
    </message>
</context>
<context>
    <name>SceneKeys</name>
    <message>
        <source>algorithm</source>
        <translation>算法</translation>
    </message>
    <message>
        <source>ambient</source>
        <translation>环境光系数</translation>
    </message>
    <message>
        <source>aperture</source>
        <translation>光圈</translation>
    </message>
    <message>
        <source>attenuation</source>
        <translation>衰减系数</translation>
    </message>
    <message>
        <source>axes</source>
        <translation>轴</translation>
    </message>
    <message>
        <source>background</source>
        <translation>背景</translation>
    </message>
    <message>
        <source>camera</source>
        <translation>相机</translation>
    </message>
    <message>
        <source>centre</source>
        <translation>中心</translation>
    </message>
    <message>
        <source>colour</source>
        <translation>颜色</translation>
    </message>
    <message>
        <source>corner</source>
        <translation>角点</translation>
    </message>
    <message>
        <source>diffuse</source>
        <translation>漫反射（Lambert）</translation>
    </message>
    <message>
        <source>distribution</source>
        <translation>微表面分布</translation>
    </message>
    <message>
        <source>emission</source>
        <translation>自发光</translation>
    </message>
    <message>
        <source>exponent</source>
        <translation>指数</translation>
    </message>
    <message>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>focus distance</source>
        <translation>对焦距离</translation>
    </message>
    <message>
        <source>fresnel</source>
        <translation>菲涅耳</translation>
    </message>
    <message>
        <source>glossy samples</source>
        <translation>光泽反射采样数</translation>
    </message>
    <message>
        <source>height</source>
        <translation>高度</translation>
    </message>
    <message>
        <source>intensity</source>
        <translation>强度</translation>
    </message>
    <message>
        <source>ior</source>
        <translation>折射率</translation>
    </message>
    <message>
        <source>ior outside</source>
        <translation>外侧折射率</translation>
    </message>
    <message>
        <source>look at</source>
        <translation>观察点</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m（经向分段）</translation>
    </message>
    <message>
        <source>material</source>
        <translation>材质</translation>
    </message>
    <message>
        <source>materials</source>
        <translation>材质</translation>
    </message>
    <message>
        <source>matrix</source>
        <translation>矩阵</translation>
    </message>
    <message>
        <source>max depth</source>
        <translation>最大深度</translation>
    </message>
    <message>
        <source>multiple importance</source>
        <translation>多重重要性采样</translation>
    </message>
    <message>
        <source>n</source>
        <translation>n（纬向分段）</translation>
    </message>
    <message>
        <source>name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>near clip</source>
        <translation>近裁剪距离</translation>
    </message>
    <message>
        <source>next event estimation</source>
        <translation>下一事件估计</translation>
    </message>
    <message>
        <source>normal</source>
        <translation>法线</translation>
    </message>
    <message>
        <source>objects</source>
        <translation>物体</translation>
    </message>
    <message>
        <source>opacity</source>
        <translation>不透明度</translation>
    </message>
    <message>
        <source>point</source>
        <translation>点</translation>
    </message>
    <message>
        <source>point lights</source>
        <translation>点光源</translation>
    </message>
    <message>
        <source>position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>radius</source>
        <translation>半径</translation>
    </message>
    <message>
        <source>ray offset</source>
        <translation>光线偏移</translation>
    </message>
    <message>
        <source>reflection rate</source>
        <translation>反射系数</translation>
    </message>
    <message>
        <source>refraction rate</source>
        <translation>折射系数</translation>
    </message>
    <message>
        <source>render</source>
        <translation>渲染</translation>
    </message>
    <message>
        <source>rotate</source>
        <translation>旋转</translation>
    </message>
    <message>
        <source>roughness</source>
        <translation>粗糙度</translation>
    </message>
    <message>
        <source>russian roulette depth</source>
        <translation>俄罗斯轮盘赌起始深度</translation>
    </message>
    <message>
        <source>scale</source>
        <translation>缩放</translation>
    </message>
    <message>
        <source>seed</source>
        <translation>随机种子</translation>
    </message>
    <message>
        <source>shadow samples</source>
        <translation>阴影采样数</translation>
    </message>
    <message>
        <source>shape</source>
        <translation>形状</translation>
    </message>
    <message>
        <source>size</source>
        <translation>尺寸</translation>
    </message>
    <message>
        <source>specular</source>
        <translation>镜面反射系数</translation>
    </message>
    <message>
        <source>spp</source>
        <translation>每像素采样数</translation>
    </message>
    <message>
        <source>transform</source>
        <translation>变换</translation>
    </message>
    <message>
        <source>translate</source>
        <translation>平移</translation>
    </message>
    <message>
        <source>type</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>u</source>
        <translation>u 边</translation>
    </message>
    <message>
        <source>up</source>
        <translation>上方向</translation>
    </message>
    <message>
        <source>v</source>
        <translation>v 边</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>vertical fov</source>
        <translation>垂直视场角</translation>
    </message>
    <message>
        <source>vertices</source>
        <translation>顶点</translation>
    </message>
    <message>
        <source>visible normals</source>
        <translation>可见法线采样</translation>
    </message>
    <message>
        <source>width</source>
        <translation>宽度</translation>
    </message>
    <message>
        <source>acceleration</source>
        <translation>加速结构</translation>
    </message>
    <message>
        <source>bvh split</source>
        <translation>BVH 划分方式</translation>
    </message>
    <message>
        <source>near clip shape</source>
        <translation>近裁剪面形状</translation>
    </message>
    <message>
        <source>crease angle</source>
        <translation>折痕角</translation>
    </message>
    <message>
        <source>normals</source>
        <translation>法线</translation>
    </message>
    <message>
        <source>axis</source>
        <translation>旋转轴</translation>
    </message>
    <message>
        <source>degrees</source>
        <translation>角度（度）</translation>
    </message>
    <message>
        <source>priority</source>
        <translation>优先级</translation>
    </message>
    <message>
        <source>display name</source>
        <translation>显示名称</translation>
    </message>
    <message>
        <source>zh</source>
        <translation>中文</translation>
    </message>
</context>
<context>
    <name>SceneValues</name>
    <message>
        <source>beckmann</source>
        <translation>Beckmann</translation>
    </message>
    <message>
        <source>blinn_phong</source>
        <translation>Blinn–Phong 光照模型</translation>
    </message>
    <message>
        <source>dielectric</source>
        <translation>电介质（菲涅耳玻璃）</translation>
    </message>
    <message>
        <source>diffuse</source>
        <translation>漫反射（Lambert）</translation>
    </message>
    <message>
        <source>exact</source>
        <translation>精确</translation>
    </message>
    <message>
        <source>ggx</source>
        <translation>GGX</translation>
    </message>
    <message>
        <source>glossy</source>
        <translation>光泽反射（Phong）</translation>
    </message>
    <message>
        <source>mirror</source>
        <translation>镜面（反射 + 折射）</translation>
    </message>
    <message>
        <source>phong</source>
        <translation>Phong 光照模型</translation>
    </message>
    <message>
        <source>rough_conductor</source>
        <translation>粗糙导体</translation>
    </message>
    <message>
        <source>rough_dielectric</source>
        <translation>粗糙电介质</translation>
    </message>
    <message>
        <source>schlick</source>
        <translation>Schlick 近似</translation>
    </message>
    <message>
        <source>bvh</source>
        <translation>BVH（包围盒层次结构）</translation>
    </message>
    <message>
        <source>median</source>
        <translation>中位数划分</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无（暴力求交）</translation>
    </message>
    <message>
        <source>sah</source>
        <translation>表面积启发式（SAH）</translation>
    </message>
    <message>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>flat</source>
        <translation>平面着色</translation>
    </message>
    <message>
        <source>smooth</source>
        <translation>平滑着色</translation>
    </message>
    <message>
        <source>plastic</source>
        <translation>塑料</translation>
    </message>
</context>
<context>
    <name>raylab::app::AnimationGroup</name>
    <message>
        <source>Bounce animation</source>
        <translation>弹射动画</translation>
    </message>
    <message>
        <source>Depth by depth</source>
        <translation>按深度逐层</translation>
    </message>
    <message>
        <source>Processing order</source>
        <translation>按处理顺序</translation>
    </message>
    <message>
        <source>Depth by depth: every ray of one depth travels at once.
Processing order: ray after ray, as the engine&apos;s queue takes them.</source>
        <translation>按深度逐层：同一深度的所有光线同时传播。
按处理顺序：按引擎队列取出光线的顺序，一条接一条地传播。</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>顺序</translation>
    </message>
    <message>
        <source>Processing order: rays that start together in one step</source>
        <translation>按处理顺序时：每一步同时出发的光线数</translation>
    </message>
    <message>
        <source>Rays per step</source>
        <translation>每步光线数</translation>
    </message>
    <message>
        <source>How fast the rays travel: frames the animation moves on per tick (%1 ticks a second), from 1/8 to 16</source>
        <translation>光线传播的快慢：动画每个节拍前进的帧数（每秒 %1 个节拍），范围为 1/8 到 16</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>帧</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>上一步</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>下一步</translation>
    </message>
    <message>
        <source>Play the bounces from where the animation stands</source>
        <translation>从动画的当前位置开始播放光线弹射</translation>
    </message>
    <message>
        <source>Stop at the current frame</source>
        <translation>停在当前帧</translation>
    </message>
    <message>
        <source>Back to the end of the previous step</source>
        <translation>回到上一步的末尾</translation>
    </message>
    <message>
        <source>On to the end of the next step</source>
        <translation>前进到下一步的末尾</translation>
    </message>
    <message>
        <source>Drag to any frame of the animation</source>
        <translation>拖动到动画的任意一帧</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>no tree yet</source>
        <translation>尚无光线树</translation>
    </message>
</context>
<context>
    <name>raylab::app::CheckDialog</name>
    <message>
        <source>differs</source>
        <translation>不一致</translation>
    </message>
    <message>
        <source>wrong type</source>
        <translation>返回类型错误</translation>
    </message>
    <message>
        <source>Check my code</source>
        <translation>检查我的代码</translation>
    </message>
    <message>
        <source>The check did not end within %1 s and was stopped.</source>
        <translation>检查在 %1 秒内没有结束，已被终止。</translation>
    </message>
    <message>
        <source>Your Python file (.py)</source>
        <translation>你的 Python 文件（.py）</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <source>&amp;Check</source>
        <translation>检查(&amp;C)</translation>
    </message>
    <message>
        <source>Choose an exercise and your file, then Check.</source>
        <translation>选择一个练习和你的文件，然后点击“检查”。</translation>
    </message>
    <message>
        <source>Your tree, coloured by verdict</source>
        <translation>你的光线树（按评判结果着色）</translation>
    </message>
    <message>
        <source>The engine&apos;s tree, by ray kind</source>
        <translation>引擎的光线树（按光线类型着色）</translation>
    </message>
    <message>
        <source>Exercise:</source>
        <translation>练习：</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>文件：</translation>
    </message>
    <message>
        <source>No exercises were found in %1.</source>
        <translation>在 %1 中没有找到练习。</translation>
    </message>
    <message>
        <source>Your Python file</source>
        <translation>你的 Python 文件</translation>
    </message>
    <message>
        <source>Python files (*.py)</source>
        <translation>Python 文件 (*.py)</translation>
    </message>
    <message>
        <source>Choose your Python file first.</source>
        <translation>请先选择你的 Python 文件。</translation>
    </message>
    <message>
        <source>%1: no such file.</source>
        <translation>%1：文件不存在。</translation>
    </message>
    <message>
        <source>Python 3 (%1) could not be started: install it (scripts/setup.sh).</source>
        <translation>无法启动 Python 3（%1）：请先安装（见 scripts/setup.sh）。</translation>
    </message>
    <message>
        <source>Checking %1 on %2 … (your code runs in a separate process)</source>
        <translation>正在用练习 %2 检查 %1 …（你的代码在独立的子进程中运行）</translation>
    </message>
    <message>
        <source>The check gave no report (exit status %1).</source>
        <translation>检查没有生成报告（退出码 %1）。</translation>
    </message>
    <message>
        <source>Every case passes.</source>
        <translation>所有用例都通过了。</translation>
    </message>
    <message>
        <source>%1 of %2 cases fail.</source>
        <translation>%2 个用例中有 %1 个未通过。</translation>
    </message>
    <message>
        <source>Your file could not be checked.</source>
        <translation>无法检查你的文件。</translation>
    </message>
    <message>
        <source>%1, line %2</source>
        <translation>%1，第 %2 行</translation>
    </message>
    <message>
        <source>Could not be checked</source>
        <translation>无法检查</translation>
    </message>
    <message>
        <source>The tree could not be read: %1</source>
        <translation>无法读取光线树：%1</translation>
    </message>
    <message>
        <source>pass</source>
        <translation>通过</translation>
    </message>
    <message>
        <source>FAIL</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>yours %1, reference %2</source>
        <translation>你的结果 %1，参考结果 %2</translation>
    </message>
    <message>
        <source>PASS: all %1 cases agree with the reference.</source>
        <translation>通过：全部 %1 个用例都与参考结果一致。</translation>
    </message>
    <message>
        <source>FAIL: %1 of %2 cases differ from the reference.</source>
        <translation>未通过：%2 个用例中有 %1 个与参考结果不一致。</translation>
    </message>
    <message>
        <source>Known bug: %1</source>
        <translation>常见错误：%1</translation>
    </message>
    <message>
        <source>Your tree: pixel (%1, %2) of the default scene, %3 rays.</source>
        <translation>你的光线树：默认场景的像素 (%1, %2)，共 %3 条光线。</translation>
    </message>
    <message>
        <source>Every ray agrees with the exact answer.</source>
        <translation>每条光线都与精确结果一致。</translation>
    </message>
    <message>
        <source>First ray that differs: ray %1 (%2)</source>
        <translation>第一条出错的光线：第 %1 号光线（%2）</translation>
    </message>
    <message>
        <source>  origin %1, direction %2, t in [%3, %4]</source>
        <translation>  起点 %1，方向 %2，t 的范围 [%3, %4]</translation>
    </message>
    <message>
        <source>  yours: t = %1
  exact: t = %2</source>
        <translation>  你的结果：t = %1
  精确结果：t = %2</translation>
    </message>
    <message>
        <source>  error: %1</source>
        <translation>  错误：%1</translation>
    </message>
    <message>
        <source>Yours</source>
        <translation>你的结果</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>参考结果</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>没有击中物体</translation>
    </message>
    <message>
        <source>Ray</source>
        <translation>光线</translation>
    </message>
    <message>
        <source>t (the function&apos;s answer)</source>
        <translation>t（函数的返回值）</translation>
    </message>
    <message>
        <source>Hits</source>
        <translation>击中的物体</translation>
    </message>
    <message>
        <source>Ends at</source>
        <translation>终点</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>法线</translation>
    </message>
    <message>
        <source>How it ends</source>
        <translation>结束方式</translation>
    </message>
</context>
<context>
    <name>raylab::app::ComparePanel</name>
    <message>
        <source>Equal samples</source>
        <translation>等采样数</translation>
    </message>
    <message>
        <source>Equal time</source>
        <translation>等时间</translation>
    </message>
    <message>
        <source>Equal samples: every algorithm takes the same samples per pixel.
Equal time: every algorithm renders for the same time (the fair race).</source>
        <translation>等采样数：每种算法的每像素采样数相同。
等时间：每种算法渲染相同的时间（公平的比赛）。</translation>
    </message>
    <message>
        <source> spp</source>
        <translation> spp</translation>
    </message>
    <message>
        <source>Samples per pixel of every algorithm (equal samples)</source>
        <translation>每种算法的每像素采样数（等采样数）</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>Rendering time of every algorithm (equal time)</source>
        <translation>每种算法的渲染时间（等时间）</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>对比</translation>
    </message>
    <message>
        <source>Render the four algorithms side by side on the open scene. Comparing again while one runs cancels it and starts over.</source>
        <translation>在当前场景上并排渲染四种算法。对比进行时再次对比，会取消当前对比并重新开始。</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Stop the comparison; the passes finished so far stay</source>
        <translation>停止对比；已完成的各遍结果会保留</translation>
    </message>
    <message>
        <source>Convergence plot</source>
        <translation>收敛曲线</translation>
    </message>
    <message>
        <source>Error against samples (or time) for each algorithm, log-log</source>
        <translation>各算法的误差随采样数（或时间）的变化，双对数坐标</translation>
    </message>
    <message>
        <source>Press Compare to render the four algorithms side by side.</source>
        <translation>按“对比”并排渲染四种算法。</translation>
    </message>
    <message>
        <source>Click a pixel of any image to trace it with all four algorithms</source>
        <translation>单击任一图像中的像素，用四种算法分别追踪它</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>Comparing: %1, %2 spp…</source>
        <translation>正在对比：%1，%2 spp…</translation>
    </message>
    <message>
        <source>Comparing…</source>
        <translation>正在对比…</translation>
    </message>
    <message>
        <source>Comparing the four algorithms on the open scene…</source>
        <translation>正在当前场景上对比四种算法…</translation>
    </message>
    <message>
        <source> (the reference came from the cache)</source>
        <translation>（参考图像取自缓存）</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>已完成</translation>
    </message>
    <message>
        <source>Comparison cancelled</source>
        <translation>对比已取消</translation>
    </message>
    <message>
        <source>Comparison done</source>
        <translation>对比已完成</translation>
    </message>
    <message>
        <source>Pixel (%1, %2) traced with every algorithm: the trees are beside the images</source>
        <translation>已用每种算法追踪像素 (%1, %2)：光线树显示在图像旁</translation>
    </message>
    <message>
        <source>the reference</source>
        <translation>参考图像</translation>
    </message>
</context>
<context>
    <name>raylab::app::EditPanel</name>
    <message>
        <source>Rotate about its centre</source>
        <translation>绕中心旋转</translation>
    </message>
    <message>
        <source>Angle, degrees (counter-clockwise about the axis)</source>
        <translation>角度，单位为度（绕旋转轴逆时针方向）</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>旋转轴</translation>
    </message>
    <message>
        <source>Rotation axis</source>
        <translation>旋转轴</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>旋转</translation>
    </message>
    <message>
        <source>Turn the selected object by the angle about the axis through its centre</source>
        <translation>将选中的物体绕过其中心的旋转轴转过指定角度</translation>
    </message>
    <message>
        <source>Move and scale</source>
        <translation>平移与缩放</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>偏移量</translation>
    </message>
    <message>
        <source>Move by, world units</source>
        <translation>平移距离，单位为世界坐标单位</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>平移</translation>
    </message>
    <message>
        <source>Move the selected object by the offset</source>
        <translation>将选中的物体按偏移量平移</translation>
    </message>
    <message>
        <source>Scale factor, the same along every axis</source>
        <translation>缩放因子，各坐标轴相同</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>缩放</translation>
    </message>
    <message>
        <source>Scale the selected object about its centre</source>
        <translation>以中心为基准缩放选中的物体</translation>
    </message>
    <message>
        <source>Uniform</source>
        <translation>等比</translation>
    </message>
    <message>
        <source>Per axis</source>
        <translation>逐轴</translation>
    </message>
    <message>
        <source>Scale factor</source>
        <translation>缩放因子</translation>
    </message>
    <message>
        <source>Scale per axis</source>
        <translation>逐轴缩放</translation>
    </message>
    <message>
        <source>Scale the selected object about its centre, axis by axis</source>
        <translation>以中心为基准，沿各坐标轴分别缩放选中的物体</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>物体</translation>
    </message>
    <message>
        <source>A new name for the selected object (names are unique)</source>
        <translation>选中物体的新名称（名称不能重复）</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>重命名</translation>
    </message>
    <message>
        <source>Give the selected object the name typed</source>
        <translation>把输入的名称赋给选中的物体</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>复制</translation>
    </message>
    <message>
        <source>Copy the selected object, moved a little so both can be seen</source>
        <translation>复制选中的物体，并把副本稍稍移开，使两者都能看见</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>删除</translation>
    </message>
    <message>
        <source>Delete the selected object (Del)</source>
        <translation>删除选中的物体（Del）</translation>
    </message>
    <message>
        <source>Selected: %1</source>
        <translation>已选中：%1</translation>
    </message>
    <message>
        <source>Select an object in the list or click it in the 3D view.</source>
        <translation>请在列表中选择一个物体，或在三维视图中单击它。</translation>
    </message>
    <message>
        <source>Rotate %1 %2° about %3</source>
        <translation>将“%1”绕 %3 轴旋转 %2°</translation>
    </message>
    <message>
        <source>Move %1 by (%2, %3, %4)</source>
        <translation>将“%1”平移 (%2, %3, %4)</translation>
    </message>
    <message>
        <source>Scale %1 by %2</source>
        <translation>将“%1”缩放 %2 倍</translation>
    </message>
    <message>
        <source>Scale %1 by (%2, %3, %4)</source>
        <translation>将“%1”按 (%2, %3, %4) 缩放</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>删除“%1”</translation>
    </message>
    <message>
        <source>Duplicate %1</source>
        <translation>复制“%1”</translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>将“%1”重命名为“%2”</translation>
    </message>
</context>
<context>
    <name>raylab::app::ImageView</name>
    <message>
        <source>Click a pixel to trace its ray tree in the 3D view; Ctrl+wheel zooms</source>
        <translation>单击一个像素，在三维视图中追踪它的光线树；Ctrl+滚轮缩放图像</translation>
    </message>
</context>
<context>
    <name>raylab::app::InspectorPanel</name>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Ray number in processing order (0 = the camera ray)</source>
        <translation>按处理顺序排列的光线编号（0 为相机光线）</translation>
    </message>
    <message>
        <source>Parent</source>
        <translation>父光线</translation>
    </message>
    <message>
        <source>Inspect the ray that spawned this one</source>
        <translation>查看产生这条光线的父光线</translation>
    </message>
    <message>
        <source>First child</source>
        <translation>第一条子光线</translation>
    </message>
    <message>
        <source>Inspect the first ray this one spawned</source>
        <translation>查看这条光线产生的第一条子光线</translation>
    </message>
    <message>
        <source>Ray #</source>
        <translation>光线 #</translation>
    </message>
    <message>
        <source>No ray tree yet: choose a pixel in the Ray tree tab and press Trace.</source>
        <translation>还没有光线树：请在“光线树”选项卡中选择一个像素，然后按“追踪”。</translation>
    </message>
    <message>
        <source>Click a ray in the 3D view, or choose its number above, to see its origin, direction, hit, material, weight, pdf and energy, and the exact oracle&apos;s check of its hit beside double precision.</source>
        <translation>在三维视图中单击一条光线，或在上方选择它的编号，即可查看它的起点、方向、交点、材质、权重、概率密度（pdf）和能量，以及精确判定器对该交点的检验与双精度结果的对照。</translation>
    </message>
    <message>
        <source>Exactness figures</source>
        <translation>精确性数据</translation>
    </message>
    <message>
        <source>Show the exact oracle&apos;s check of this ray&apos;s hit (CGAL, exact numbers) beside double precision: the t values, their difference in ulps and the error bound</source>
        <translation>显示精确判定器（CGAL，精确数值运算）对这条光线交点的检验，并与双精度结果对照：t 值、二者相差多少个 ulp，以及误差界</translation>
    </message>
    <message>
        <source>(The exact oracle&apos;s check of the hit: press Exactness figures in the Ray inspector.)</source>
        <translation>（精确判定器对交点的检验：在“光线检查器”中按“精确性数据”按钮即可查看。）</translation>
    </message>
    <message>
        <source>weight: what this ray&apos;s light is multiplied by where it joins its parent.
pdf: the probability density with which this direction was sampled (none: a fixed direction, such as a mirror&apos;s, a refraction&apos;s or a shadow ray&apos;s).
throughput: the share of light this path passes on to the camera, the product of the weights from the camera to here.</source>
        <translation>权重（weight）：这条光线的光汇入其父光线时要乘上的系数。
概率密度（pdf）：抽样得到这个方向的概率密度（无：方向是确定的，例如镜面反射、折射或阴影光线）。
路径吞吐量（throughput）：这条路径把光传回相机时保留的比例，即从相机到此处各段权重的乘积。</translation>
    </message>
</context>
<context>
    <name>raylab::app::LessonPanel</name>
    <message>
        <source>The language of the lesson&apos;s texts</source>
        <translation>课程文字所用的语言</translation>
    </message>
    <message>
        <source>Question</source>
        <translation>问题</translation>
    </message>
    <message>
        <source>Your answer (a number)</source>
        <translation>你的答案（一个数值）</translation>
    </message>
    <message>
        <source>Check my answer</source>
        <translation>检查答案</translation>
    </message>
    <message>
        <source>Teacher&apos;s notes</source>
        <translation>教师备注</translation>
    </message>
    <message>
        <source>Show or hide the notes for the teacher</source>
        <translation>显示或隐藏给教师的备注</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>上一步</translation>
    </message>
    <message>
        <source>The previous step (Page Up)</source>
        <translation>上一步（Page Up）</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>下一步</translation>
    </message>
    <message>
        <source>The next step (Page Down)</source>
        <translation>下一步（Page Down）</translation>
    </message>
    <message>
        <source>No lesson</source>
        <translation>未打开课程</translation>
    </message>
    <message>
        <source>Choose a lesson in the Lessons menu.</source>
        <translation>请在“课程”菜单中选择一节课。</translation>
    </message>
    <message>
        <source>Step %1 of %2</source>
        <translation>第 %1 步（共 %2 步）</translation>
    </message>
    <message>
        <source>This step needs a feature still to come (%1): the view shows the scene instead.</source>
        <translation>本步骤需要一个尚未实现的功能（%1）：这里暂以场景视图代替。</translation>
    </message>
    <message>
        <source>Predict first: the view shows the answer once you have answered.</source>
        <translation>先预测：作答之后，视图才会显示答案。</translation>
    </message>
    <message>
        <source>Say whether the answer is right (Enter)</source>
        <translation>判断答案是否正确（回车键）</translation>
    </message>
    <message>
        <source>Show answer</source>
        <translation>显示答案</translation>
    </message>
    <message>
        <source>Show the answer and why, without another try</source>
        <translation>不再尝试，直接显示答案及解释</translation>
    </message>
    <message>
        <source>Change a value</source>
        <translation>改一个参数</translation>
    </message>
    <message>
        <source>The value to try; then show its effect</source>
        <translation>要尝试的数值；然后显示它的效果</translation>
    </message>
    <message>
        <source>Show the effect</source>
        <translation>显示效果</translation>
    </message>
    <message>
        <source>Trace and render the step&apos;s scene with this value</source>
        <translation>用这个数值追踪并渲染本步骤的场景</translation>
    </message>
    <message>
        <source>%1 (now %2; the task: %3)</source>
        <translation>%1（当前 %2；任务：%3）</translation>
    </message>
</context>
<context>
    <name>raylab::app::MainWindow</name>
    <message>
        <source>Image</source>
        <translation>图像</translation>
    </message>
    <message>
        <source>The scene&apos;s objects: select one to edit it (Esc: none)</source>
        <translation>场景中的物体：选中一个即可编辑（Esc：取消选择）</translation>
    </message>
    <message>
        <source>Objects</source>
        <translation>物体</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>编辑</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>属性</translation>
    </message>
    <message>
        <source>Edit refused</source>
        <translation>无法编辑</translation>
    </message>
    <message>
        <source>Value refused</source>
        <translation>无法接受该值</translation>
    </message>
    <message>
        <source>Ray tree</source>
        <translation>光线树</translation>
    </message>
    <message>
        <source>Ray inspector</source>
        <translation>光线检查器</translation>
    </message>
    <message>
        <source>Drag to rotate, wheel to zoom, click an object to select it; trace a pixel on the right</source>
        <translation>拖动旋转，滚轮缩放，单击物体将其选中；在右侧追踪一个像素</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>新建(&amp;N)</translation>
    </message>
    <message>
        <source>Start again from the built-in default scene</source>
        <translation>从内置的默认场景重新开始</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <source>Open a scene file (.json)</source>
        <translation>打开场景文件（.json）</translation>
    </message>
    <message>
        <source>Open a scene</source>
        <translation>打开场景</translation>
    </message>
    <message>
        <source>RayLab scenes (*.json)</source>
        <translation>RayLab 场景 (*.json)</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <source>Save the scene to its file</source>
        <translation>将场景保存到其文件</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>Save the scene to another file</source>
        <translation>将场景保存到另一个文件</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>还原(&amp;V)</translation>
    </message>
    <message>
        <source>Read the scene&apos;s file again, dropping every edit</source>
        <translation>重新读取场景文件，放弃所有编辑</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>Close RayLab</source>
        <translation>关闭 RayLab</translation>
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
        <source>&amp;Delete</source>
        <translation>删除(&amp;D)</translation>
    </message>
    <message>
        <source>Delete the selected object</source>
        <translation>删除选中的物体</translation>
    </message>
    <message>
        <source>Copy the selected object</source>
        <translation>复制选中的物体</translation>
    </message>
    <message>
        <source>Clear the selection</source>
        <translation>取消选择</translation>
    </message>
    <message>
        <source>Select no object</source>
        <translation>不选中任何物体</translation>
    </message>
    <message>
        <source>&amp;Add</source>
        <translation>添加(&amp;A)</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>球体</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>长方体</translation>
    </message>
    <message>
        <source>Plane</source>
        <translation>平面</translation>
    </message>
    <message>
        <source>Quad</source>
        <translation>四边形</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation>三角形</translation>
    </message>
    <message>
        <source>Add a %1 where the camera looks</source>
        <translation>在相机注视的位置添加一个%1</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>添加%1</translation>
    </message>
    <message>
        <source>Mesh from a file…</source>
        <translation>从文件导入网格…</translation>
    </message>
    <message>
        <source>Add a mesh (OBJ, PLY, OFF, STL)</source>
        <translation>添加网格（OBJ、PLY、OFF、STL）</translation>
    </message>
    <message>
        <source>Add a mesh</source>
        <translation>添加网格</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.ply *.off *.stl)</source>
        <translation>网格 (*.obj *.ply *.off *.stl)</translation>
    </message>
    <message>
        <source>Add mesh %1</source>
        <translation>添加网格 %1</translation>
    </message>
    <message>
        <source>Point light</source>
        <translation>点光源</translation>
    </message>
    <message>
        <source>Add a point light above where the camera looks</source>
        <translation>在相机注视位置的上方添加一个点光源</translation>
    </message>
    <message>
        <source>Add point light</source>
        <translation>添加点光源</translation>
    </message>
    <message>
        <source>&amp;Render</source>
        <translation>渲染(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Render image</source>
        <translation>渲染图像(&amp;R)</translation>
    </message>
    <message>
        <source>Render the scene camera&apos;s image with the chosen algorithm, pass by pass</source>
        <translation>用所选算法逐遍渲染场景相机看到的图像</translation>
    </message>
    <message>
        <source>&amp;Cancel render</source>
        <translation>取消渲染(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Save image…</source>
        <translation>保存图像(&amp;S)…</translation>
    </message>
    <message>
        <source>Save the rendered image (PNG or PFM)</source>
        <translation>保存渲染出的图像（PNG 或 PFM）</translation>
    </message>
    <message>
        <source>Zoom &amp;in</source>
        <translation>放大(&amp;I)</translation>
    </message>
    <message>
        <source>Zoom into the image: pixels become squares</source>
        <translation>放大图像：像素显示为小方块</translation>
    </message>
    <message>
        <source>Zoom &amp;out</source>
        <translation>缩小(&amp;O)</translation>
    </message>
    <message>
        <source>Zoom out of the image</source>
        <translation>缩小图像</translation>
    </message>
    <message>
        <source>&amp;Fit the image</source>
        <translation>适应窗口(&amp;F)</translation>
    </message>
    <message>
        <source>Show the whole image</source>
        <translation>显示整幅图像</translation>
    </message>
    <message>
        <source>&amp;Animation</source>
        <translation>动画(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Play / pause</source>
        <translation>播放/暂停(&amp;P)</translation>
    </message>
    <message>
        <source>Play the bounce animation, or pause it</source>
        <translation>播放光线弹射动画，或将其暂停</translation>
    </message>
    <message>
        <source>Step &amp;forward</source>
        <translation>下一步(&amp;F)</translation>
    </message>
    <message>
        <source>Show the next step of the ray tree</source>
        <translation>显示光线树的下一步</translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation>上一步(&amp;B)</translation>
    </message>
    <message>
        <source>Go back to the previous step</source>
        <translation>回到上一步</translation>
    </message>
    <message>
        <source>F&amp;irst frame</source>
        <translation>第一帧(&amp;I)</translation>
    </message>
    <message>
        <source>Back to the start: no ray drawn yet</source>
        <translation>回到开头：尚未画出任何光线</translation>
    </message>
    <message>
        <source>&amp;Last frame</source>
        <translation>最后一帧(&amp;L)</translation>
    </message>
    <message>
        <source>The whole tree</source>
        <translation>整棵光线树</translation>
    </message>
    <message>
        <source>F&amp;aster</source>
        <translation>加快(&amp;A)</translation>
    </message>
    <message>
        <source>Play the animation twice as fast</source>
        <translation>以两倍速度播放动画</translation>
    </message>
    <message>
        <source>Play the animation half as fast</source>
        <translation>以一半速度播放动画</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Presentation mode</source>
        <translation>演示模式(&amp;P)</translation>
    </message>
    <message>
        <source>Full screen, large fonts and thick rays, for the back of a classroom (F11 again to leave)</source>
        <translation>全屏、大字体、粗光线，教室后排也能看清（再按 F11 退出）</translation>
    </message>
    <message>
        <source>&amp;Image beside the 3D view</source>
        <translation>在三维视图旁显示图像(&amp;I)</translation>
    </message>
    <message>
        <source>Show or hide the rendered image and the comparison</source>
        <translation>显示或隐藏渲染图像和对比图</translation>
    </message>
    <message>
        <source>&amp;Reset view</source>
        <translation>重置视图(&amp;R)</translation>
    </message>
    <message>
        <source>Look at the whole scene again</source>
        <translation>重新看到整个场景</translation>
    </message>
    <message>
        <source>Show or hide the %1 panel</source>
        <translation>显示或隐藏“%1”面板</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>Show the window in this language</source>
        <translation>以这种语言显示窗口</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <source>Every shortcut and mouse gesture of the window</source>
        <translation>本窗口的全部快捷键和鼠标操作</translation>
    </message>
    <message>
        <source>Presentation mode: F11 leaves it; Space plays the animation, Left and Right step it</source>
        <translation>演示模式：按 F11 退出；空格键播放动画，左、右方向键逐步后退、前进</translation>
    </message>
    <message>
        <source>Presentation mode off</source>
        <translation>已退出演示模式</translation>
    </message>
    <message>
        <source>3D view</source>
        <translation>三维视图</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>拖动</translation>
    </message>
    <message>
        <source>Rotate the view around the scene</source>
        <translation>绕场景旋转视图</translation>
    </message>
    <message>
        <source>Wheel</source>
        <translation>滚轮</translation>
    </message>
    <message>
        <source>Zoom in and out</source>
        <translation>放大和缩小</translation>
    </message>
    <message>
        <source>Click</source>
        <translation>单击</translation>
    </message>
    <message>
        <source>Select the ray or the object under the cursor</source>
        <translation>选中光标下的光线或物体</translation>
    </message>
    <message>
        <source>Trace that pixel&apos;s ray tree in the 3D view</source>
        <translation>在三维视图中追踪该像素的光线树</translation>
    </message>
    <message>
        <source>Ctrl+Wheel</source>
        <translation>Ctrl+滚轮</translation>
    </message>
    <message>
        <source>Zoom the image (pixels stay square)</source>
        <translation>缩放图像（像素保持方形）</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>按键</translation>
    </message>
    <message>
        <source>What it does</source>
        <translation>作用</translation>
    </message>
    <message>
        <source>Pixel (%1, %2) traced with %3: its ray tree is in the 3D view</source>
        <translation>已追踪像素 (%1, %2)，算法：%3；它的光线树显示在三维视图中</translation>
    </message>
    <message>
        <source>Cannot save the image</source>
        <translation>无法保存图像</translation>
    </message>
    <message>
        <source>There is no image to save yet: press Render first.</source>
        <translation>还没有可保存的图像：请先按“渲染”。</translation>
    </message>
    <message>
        <source>Save the image</source>
        <translation>保存图像</translation>
    </message>
    <message>
        <source>PNG image (*.png);;PFM, linear radiance (*.pfm)</source>
        <translation>PNG 图像 (*.png);;PFM 线性辐射亮度 (*.pfm)</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>Cannot add</source>
        <translation>无法添加</translation>
    </message>
    <message>
        <source>Ray #%1 selected: see the Ray inspector tab</source>
        <translation>已选中光线 #%1：请查看“光线检查器”选项卡</translation>
    </message>
    <message>
        <source>Nothing under the cursor</source>
        <translation>光标下没有任何东西</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>未保存的更改</translation>
    </message>
    <message>
        <source>The scene has changes that are not saved. Save them?</source>
        <translation>场景有尚未保存的更改。要保存吗？</translation>
    </message>
    <message>
        <source>Cannot open the scene</source>
        <translation>无法打开场景</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>已打开 %1</translation>
    </message>
    <message>
        <source>Cannot save the scene</source>
        <translation>无法保存场景</translation>
    </message>
    <message>
        <source>Save the scene</source>
        <translation>保存场景</translation>
    </message>
    <message>
        <source>The built-in default scene</source>
        <translation>内置的默认场景</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>还原</translation>
    </message>
    <message>
        <source>Drop every change since the file was saved?</source>
        <translation>放弃自上次保存文件以来的所有更改吗？</translation>
    </message>
    <message>
        <source>Cannot read the scene again</source>
        <translation>无法重新读取场景</translation>
    </message>
    <message>
        <source>The built-in default scene (no scene was open last time)</source>
        <translation>内置的默认场景（上次没有打开场景）</translation>
    </message>
    <message>
        <source>Opened %1, the scene open last time</source>
        <translation>已打开上次打开的场景 %1</translation>
    </message>
    <message>
        <source>The built-in default scene: the scene open last time could not be read (%1)</source>
        <translation>内置的默认场景：无法读取上次打开的场景（%1）</translation>
    </message>
    <message>
        <source>Du&amp;plicate</source>
        <translation>复制(&amp;P)</translation>
    </message>
    <message>
        <source>Slo&amp;wer</source>
        <translation>减速(&amp;W)</translation>
    </message>
    <message>
        <source>Lesson</source>
        <translation>课程</translation>
    </message>
    <message>
        <source>Less&amp;ons</source>
        <translation>课程(&amp;O)</translation>
    </message>
    <message>
        <source>Open a lesson &amp;file…</source>
        <translation>打开课程文件(&amp;F)…</translation>
    </message>
    <message>
        <source>Open a lesson file (.json) of your own</source>
        <translation>打开你自己编写的课程文件（.json）</translation>
    </message>
    <message>
        <source>Open a lesson</source>
        <translation>打开课程</translation>
    </message>
    <message>
        <source>RayLab lessons (*.json)</source>
        <translation>RayLab 课程 (*.json)</translation>
    </message>
    <message>
        <source>&amp;Next step</source>
        <translation>下一步(&amp;N)</translation>
    </message>
    <message>
        <source>The lesson&apos;s next step</source>
        <translation>课程的下一步</translation>
    </message>
    <message>
        <source>&amp;Previous step</source>
        <translation>上一步(&amp;P)</translation>
    </message>
    <message>
        <source>The lesson&apos;s previous step</source>
        <translation>课程的上一步</translation>
    </message>
    <message>
        <source>Cannot open the lesson</source>
        <translation>无法打开课程</translation>
    </message>
    <message>
        <source>%1: the lesson has no steps</source>
        <translation>%1：这节课没有任何步骤</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>对比</translation>
    </message>
    <message>
        <source>C&amp;ompare the four algorithms</source>
        <translation>对比四种算法(&amp;O)</translation>
    </message>
    <message>
        <source>Render ray casting, Whitted, distributed and path tracing side by side on this scene, with their figures and errors</source>
        <translation>在此场景上并排渲染光线投射、Whitted、分布式与路径追踪，并给出各自的数据和误差</translation>
    </message>
    <message>
        <source>Stop the render, the comparison and a trace; what is done so far stays</source>
        <translation>停止渲染、对比和追踪；已完成的部分会保留</translation>
    </message>
    <message>
        <source>Take back the last edit (the menu names it)</source>
        <translation>撤销上一次编辑（菜单中写明是哪一次）</translation>
    </message>
    <message>
        <source>Do again the edit just taken back</source>
        <translation>重做刚刚撤销的编辑</translation>
    </message>
    <message>
        <source>Cannot use this value</source>
        <translation>无法使用这个数值</translation>
    </message>
    <message>
        <source>&amp;Check my code…</source>
        <translation>检查我的代码(&amp;C)…</translation>
    </message>
    <message>
        <source>Check your own function of an exercise against the reference</source>
        <translation>用参考实现检查你为练习编写的函数</translation>
    </message>
    <message>
        <source>&amp;Continue the last lesson</source>
        <translation>继续上次的课程(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Continue: %1, step %2</source>
        <translation>继续上次的课程(&amp;C)：%1，第 %2 步</translation>
    </message>
    <message>
        <source>Reopen the lesson shown last, at the step it was left at</source>
        <translation>重新打开上次讲到的课程，并回到停下的那一步</translation>
    </message>
    <message>
        <source>drawn with %1 bands x %2 slices</source>
        <translation>绘制时分为 %1 段（从极到极）× %2 段（绕轴一周）</translation>
    </message>
</context>
<context>
    <name>raylab::app::PropertiesPanel</name>
    <message>
        <source>Shape of %1</source>
        <translation>“%1”的形状</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>材质</translation>
    </message>
    <message>
        <source>The material this object is made of (shared with other objects)</source>
        <translation>这个物体所用的材质（与其他物体共用）</translation>
    </message>
    <message>
        <source>Use material %1</source>
        <translation>使用材质“%1”</translation>
    </message>
    <message>
        <source>uses</source>
        <translation>使用</translation>
    </message>
    <message>
        <source>Material %1</source>
        <translation>材质“%1”</translation>
    </message>
    <message>
        <source>Motion over the shutter</source>
        <translation>快门期间的运动</translation>
    </message>
    <message>
        <source>Velocity, world units over the shutter interval (motion blur)</source>
        <translation>速度，即快门时间段内移动的世界坐标单位数（运动模糊）</translation>
    </message>
    <message>
        <source>Set velocity</source>
        <translation>设置速度</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>相机</translation>
    </message>
    <message>
        <source>Render settings</source>
        <translation>渲染设置</translation>
    </message>
    <message>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <source>Choose the colour</source>
        <translation>选择颜色</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>颜色</translation>
    </message>
    <message>
        <source>Set %1 of %2</source>
        <translation>设置 %1（%2）</translation>
    </message>
    <message>
        <source>%1 (%2 in the scene file)</source>
        <translation>%1（场景文件中的 %2）</translation>
    </message>
    <message>
        <source>Diffuse coefficient kd of the Phong model, in [0, 1]</source>
        <translation>漫反射系数 kd（Phong 模型），取值 [0, 1]</translation>
    </message>
    <message>
        <source>Roughness alpha: the width of the microfacet distribution (&gt; 0, about the RMS slope of the microfacets)</source>
        <translation>粗糙度 α：微表面法线分布的宽度（&gt; 0，约等于微表面斜率的均方根）</translation>
    </message>
    <message>
        <source>Index of refraction of the medium on the outer side of this surface (1 for air)</source>
        <translation>外侧折射率：该表面外侧（法线所指一侧）介质的折射率（空气为 1）</translation>
    </message>
    <message>
        <source>Ambient coefficient times the ambient light, ka Ia (RGB, &gt;= 0); the surface returns ambient times colour</source>
        <translation>环境光系数乘以环境光强度，即 ka·Ia（RGB，≥ 0）；表面返回的环境光为该值乘以颜色</translation>
    </message>
    <message>
        <source>Attenuation coefficients [c, l, q]: light falls off with distance d as 1 / (c + l d + q d^2); [0, 0, 1] is the physical 1 / d^2, [1, 0, 0] no falloff</source>
        <translation>衰减系数 [c, l, q]：光强随距离 d 按 1 / (c + l·d + q·d²) 衰减；[0, 0, 1] 即物理上的 1 / d²，[1, 0, 0] 表示不衰减</translation>
    </message>
    <message>
        <source>Visible normal sampling: sample only the microfacet normals the viewer sees (Heitz 2018; GGX only)</source>
        <translation>可见法线采样：只对观察方向可见的微表面法线进行采样（Heitz 2018；仅适用于 GGX）</translation>
    </message>
    <message>
        <source>Microfacet distribution: ggx (Trowbridge-Reitz, long tails) or beckmann (Gaussian slopes)</source>
        <translation>微表面分布：ggx（GGX，即 Trowbridge-Reitz 分布，拖尾较长）或 beckmann（Beckmann 分布，斜率服从高斯分布）</translation>
    </message>
    <message>
        <source>Ray offset: secondary and shadow rays start past the hit point&apos;s error bound; switched off, shadow acne appears</source>
        <translation>光线偏移：次级光线和阴影光线从交点的误差界之外出发；关闭后会出现阴影失真（shadow acne）</translation>
    </message>
    <message>
        <source>How rays search the meshes: bvh (through their bounding volume hierarchy) or none (brute force, every triangle; the same image, slower)</source>
        <translation>光线如何在网格中求交：bvh（通过包围盒层次结构）或 none（暴力求交，逐一检验每个三角形；图像相同，但更慢）</translation>
    </message>
    <message>
        <source>How the meshes&apos; hierarchies split their boxes: sah (surface area heuristic) or median (half of the triangles on each side); the same image</source>
        <translation>网格的层次结构如何划分包围盒：sah（表面积启发式）或 median（中位数划分，两边各放一半三角形）；图像相同</translation>
    </message>
    <message>
        <source>Where camera rays start, near clip away from the eye: on a plane in front of the eye (plane) or along each ray (sphere, as smallpt)</source>
        <translation>相机光线的起点，与视点相距“近裁剪距离”：plane 表示在视点正前方的平面上，sphere 表示沿每条光线量取（即以视点为球心的球面上，与 smallpt 相同）</translation>
    </message>
    <message>
        <source>Shading normals of the mesh: file (the file&apos;s vertex normals, flat without them), flat (each triangle&apos;s own normal) or smooth (computed, with the crease angle)</source>
        <translation>网格的着色法线：file（使用文件中的顶点法线，文件中没有时按平面着色）、flat（每个三角形用自身的法线）或 smooth（按折痕角计算顶点法线）</translation>
    </message>
    <message>
        <source>Crease angle in degrees [0, 180]: edges between faces whose normals differ by more stay sharp when the normals are smooth</source>
        <translation>折痕角，单位为度，范围 [0, 180]：平滑着色时，相邻面法线夹角大于此值的棱边保持锐利</translation>
    </message>
    <message>
        <source>Transform of %1</source>
        <translation>%1 的变换</translation>
    </message>
    <message>
        <source>The steps the scene file applies to the shape, in order: the shape&apos;s values above are the ones before them</source>
        <translation>场景文件按顺序对形状施加的变换步骤：上面的形状参数是变换之前的值</translation>
    </message>
    <message>
        <source>Fresnel reflectance: exact (the Fresnel equations) or schlick (Schlick&apos;s approximation). For mirror, phong and blinn_phong: none keeps the constant reflection and refraction rates kr and kt; exact or schlick weighs the reflected ray kr R and the refracted ray kt (1 - R), R the reflectance at the hit</source>
        <translation>菲涅耳反射率：exact（精确，按菲涅耳公式计算）或 schlick（Schlick 近似）。对 mirror、phong 和 blinn_phong：none 保持恒定的反射系数 kr 和折射系数 kt；exact 或 schlick 则让反射光线的权重为 kr R、折射光线的权重为 kt (1 - R)，R 为交点处的菲涅耳反射率</translation>
    </message>
    <message>
        <source>Nested media: 0, this surface names the media on its two sides (ior, ior outside); 1 or more, the object is a volume of index ior, and where volumes overlap the one of higher priority fills the overlap (a glass lens in water: glass 2, water 1)</source>
        <translation>嵌套介质：0 表示该表面自行给出两侧介质的折射率（折射率、外侧折射率）；1 及以上表示该物体是折射率为 ior 的介质体，几个介质体重叠时，重叠部分由优先级较高的介质占据（例如水中的玻璃透镜：玻璃 2，水 1）</translation>
    </message>
    <message>
        <source>Scattering model: diffuse (Lambert), mirror (reflection and refraction rates), dielectric (Fresnel glass), glossy (Phong), phong (the classic Phong model: ambient, diffuse, specular), blinn_phong (Phong with Blinn&apos;s half-vector highlight), rough_conductor (microfacet metal), rough_dielectric (microfacet glass), plastic (a rough dielectric coating over a diffuse base)</source>
        <translation>散射模型：diffuse（Lambert 漫反射）、mirror（镜面，按反射系数和折射系数分配）、dielectric（按菲涅耳公式计算的玻璃）、glossy（Phong 光泽反射）、phong（经典 Phong 光照模型：环境光、漫反射、镜面反射）、blinn_phong（采用 Blinn 半程向量高光的 Phong 模型）、rough_conductor（粗糙导体，微表面金属）、rough_dielectric（粗糙电介质，微表面玻璃）、plastic（塑料：漫反射底层上覆一层粗糙电介质涂层）</translation>
    </message>
    <message>
        <source>A solid checker on the colour: space is cut into cubes of side &quot;checker scale&quot;, which take the colour and the second colour in turn (for depth of field and aliasing)</source>
        <translation>在颜色上叠加三维（实体）棋盘格纹理：空间被划分为边长为“棋盘格尺寸”的立方体，相邻立方体交替取“颜色”和“第二颜色”（用于观察景深和走样）</translation>
    </message>
    <message>
        <source>checker texture</source>
        <translation>棋盘格纹理</translation>
    </message>
    <message>
        <source>checker scale</source>
        <translation>棋盘格尺寸</translation>
    </message>
    <message>
        <source>second colour</source>
        <translation>第二颜色</translation>
    </message>
    <message>
        <source>Side of a checker cube, world units (&gt; 0)</source>
        <translation>棋盘格立方体的边长，世界坐标单位（&gt; 0）</translation>
    </message>
    <message>
        <source>The colour of every other checker cube, linear RGB in [0, 1]</source>
        <translation>每隔一个棋盘格立方体所取的颜色，线性 RGB，取值 [0, 1]</translation>
    </message>
    <message>
        <source>How finely the sphere is drawn in the 3D view: m bands from pole to pole, n slices around its axis (the rays still meet the exact sphere)</source>
        <translation>三维视图中球面绘制的精细程度：m 为从一极到另一极的分段数，n 为绕轴一周的分段数（光线求交仍使用精确的球面）</translation>
    </message>
    <message>
        <source>m (bands from pole to pole)</source>
        <translation>m（从极到极的分段数）</translation>
    </message>
    <message>
        <source>n (slices around the axis)</source>
        <translation>n（绕轴一周的分段数）</translation>
    </message>
    <message>
        <source>Blinn-Phong</source>
        <translation>Blinn–Phong 光照模型</translation>
    </message>
    <message>
        <source>rough metal</source>
        <translation>粗糙导体</translation>
    </message>
    <message>
        <source>rough glass</source>
        <translation>粗糙电介质</translation>
    </message>
    <message>
        <source>&quot;%1&quot; in the scene file</source>
        <translation>场景文件中写作“%1”</translation>
    </message>
</context>
<context>
    <name>raylab::app::RayTreePanel</name>
    <message>
        <source>Choose a pixel and press Trace to record its ray tree.</source>
        <translation>选择一个像素，然后按“追踪”记录它的光线树。</translation>
    </message>
    <message>
        <source>Tracing… (Cancel stops it)</source>
        <translation>正在追踪…（按“取消”可停止）</translation>
    </message>
    <message numerus="yes">
        <source>The filters hide %n of these rays.</source>
        <translation>
            <numerusform>其中 %n 条光线被筛选条件隐藏。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>raylab::app::RenderPanel</name>
    <message>
        <source>The algorithm that renders the image</source>
        <translation>渲染图像所用的算法</translation>
    </message>
    <message>
        <source> spp</source>
        <translation> spp</translation>
    </message>
    <message>
        <source>Samples per pixel the render stops at; the image refines pass by pass (1, 2, 4, 8, … samples)</source>
        <translation>渲染到此每像素采样数时停止；图像逐遍细化（每像素 1、2、4、8、… 个采样）</translation>
    </message>
    <message>
        <source>Render</source>
        <translation>渲染</translation>
    </message>
    <message>
        <source>Render the scene camera&apos;s image (F5). Rendering again while a render runs cancels it and starts over: two renders never run at once.</source>
        <translation>渲染场景相机看到的图像（F5）。渲染进行时再次渲染，会取消当前渲染并重新开始：两个渲染不会同时运行。</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Stop the render; the passes finished so far stay</source>
        <translation>停止渲染；已完成的各遍结果会保留</translation>
    </message>
    <message>
        <source>Save image…</source>
        <translation>保存图像…</translation>
    </message>
    <message>
        <source>Save the image as PNG (as shown) or PFM (linear radiance)</source>
        <translation>将图像保存为 PNG（与显示一致）或 PFM（线性辐射亮度）</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>适应窗口</translation>
    </message>
    <message>
        <source>Show the whole image</source>
        <translation>显示整幅图像</translation>
    </message>
    <message>
        <source>Zoom out (Ctrl+wheel)</source>
        <translation>缩小（Ctrl+滚轮）</translation>
    </message>
    <message>
        <source>Zoom in: pixels become squares (Ctrl+wheel)</source>
        <translation>放大：像素显示为小方块（Ctrl+滚轮）</translation>
    </message>
    <message>
        <source>Press Render (F5) to render the scene camera&apos;s image.
Then click a pixel to see its ray tree.</source>
        <translation>按“渲染”（F5）渲染场景相机看到的图像。
然后单击一个像素，查看它的光线树。</translation>
    </message>
    <message>
        <source>Point at a pixel to read its value</source>
        <translation>将鼠标指向一个像素即可读出它的值</translation>
    </message>
    <message>
        <source>Pixel (%1, %2): %3</source>
        <translation>像素 (%1, %2)：%3</translation>
    </message>
    <message>
        <source>Rendering with %1…</source>
        <translation>正在渲染：%1…</translation>
    </message>
    <message>
        <source>Rendering %1 × %2 with %3, %4 spp</source>
        <translation>正在渲染 %1 × %2 的图像：%3，%4 spp</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>Rendering…</source>
        <translation>正在渲染…</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>已完成</translation>
    </message>
    <message>
        <source>Render cancelled at %1 spp</source>
        <translation>渲染已在 %1 spp 时取消</translation>
    </message>
    <message>
        <source>Rendered in %1 s</source>
        <translation>渲染完成，用时 %1 秒</translation>
    </message>
    <message>
        <source>There is no image to save yet: press Render first.</source>
        <translation>还没有可保存的图像：请先按“渲染”。</translation>
    </message>
    <message>
        <source>%1 %2 / %3 spp · %4 s · %5 rays/s</source>
        <translation>%1 %2 / %3 spp · %4 秒 · %5 条光线/秒</translation>
    </message>
    <message>
        <source>brute force, no BVH</source>
        <translation>暴力求交，不用包围盒层次结构</translation>
    </message>
    <message>
        <source>BVH with median split</source>
        <translation>包围盒层次结构，中位数划分</translation>
    </message>
    <message>
        <source>%1. Warning: %2 of its samples reached the cap of %3 rays per sample, so some pixels miss light (fewer glossy or shadow samples, or a smaller max depth, avoid it)</source>
        <translation>%1。警告：有 %2 个样本达到了每个样本 %3 条光线的上限，超出部分的光线没有追踪，因此部分像素缺少光照（减少光泽或阴影采样数，或降低最大深度，即可避免）</translation>
    </message>
    <message>
        <source>capped samples: %1</source>
        <translation>达到光线上限的样本：%1</translation>
    </message>
</context>
<context>
    <name>raylab::app::SceneDocument</name>
    <message>
        <source>the unsaved scene</source>
        <translation>未保存的场景</translation>
    </message>
</context>
<context>
    <name>raylab::app::StyleGroup</name>
    <message>
        <source>Colours and filters</source>
        <translation>着色与筛选</translation>
    </message>
    <message>
        <source>Energy (grey, green, blue)</source>
        <translation>能量（灰、绿、蓝）</translation>
    </message>
    <message>
        <source>Ray kind</source>
        <translation>光线类型</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>深度</translation>
    </message>
    <message>
        <source>Energy: the share of the pixel&apos;s light that came back along the ray
(light grey = none, green = some, blue = most).</source>
        <translation>能量：像素接收的光中沿这条光线传回的份额
（浅灰 = 没有，绿 = 一部分，蓝 = 大部分）。</translation>
    </message>
    <message>
        <source>Colour by</source>
        <translation>着色依据</translation>
    </message>
    <message>
        <source>all</source>
        <translation>全部</translation>
    </message>
    <message>
        <source>Hide rays deeper than this (camera rays have depth 0)</source>
        <translation>隐藏深度大于此值的光线（相机光线的深度为 0）</translation>
    </message>
    <message>
        <source>Max depth</source>
        <translation>最大深度</translation>
    </message>
    <message>
        <source>Hide rays that carry less energy than this</source>
        <translation>隐藏携带能量小于此值的光线</translation>
    </message>
    <message>
        <source>Min energy</source>
        <translation>最小能量</translation>
    </message>
    <message>
        <source>Only paths that reached a light</source>
        <translation>只显示到达光源的路径</translation>
    </message>
    <message>
        <source>Hide rays whose subtree found no light</source>
        <translation>隐藏子树中没有找到光源的光线</translation>
    </message>
    <message>
        <source>Draw %1 rays</source>
        <translation>绘制%1光线</translation>
    </message>
    <message>
        <source>Kinds</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Hit points</source>
        <translation>交点</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>法线</translation>
    </message>
    <message>
        <source>Arrows</source>
        <translation>箭头</translation>
    </message>
    <message>
        <source>Legend</source>
        <translation>图例</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>显示</translation>
    </message>
    <message>
        <source>Every hit along the ray</source>
        <translation>光线上的所有交点</translation>
    </message>
    <message>
        <source>Mark every surface the selected ray (else the camera ray) crosses, not only the first: green where it enters a solid, red where it leaves, yellow on an open surface</source>
        <translation>标出选中的光线（未选中时为相机光线）穿过的每一个表面，而不只是第一个：进入实体处为绿色，离开处为红色，穿过开放曲面处为黄色</translation>
    </message>
</context>
<context>
    <name>raylab::app::TraceGroup</name>
    <message>
        <source>Trace a pixel</source>
        <translation>追踪一个像素</translation>
    </message>
    <message>
        <source>Ray casting: camera ray, local shading, shadow rays.
Whitted: + perfect reflection and refraction, recursively.
Distributed: many rays per bounce (soft shadows, gloss).
Path tracing: one sampled continuation per bounce, Russian roulette.</source>
        <translation>光线投射：相机光线、局部光照、阴影光线。
Whitted：再加上理想反射和折射，递归追踪。
分布式：每次弹射发出多条光线（软阴影、光泽反射）。
路径追踪：每次弹射只采样一条延续光线，并用俄罗斯轮盘赌终止。</translation>
    </message>
    <message>
        <source>Algorithm</source>
        <translation>算法</translation>
    </message>
    <message>
        <source>Pixel column, 0 at the left (the film is %1 x %2)</source>
        <translation>像素的列号，最左列为 0（图像为 %1 × %2 像素）</translation>
    </message>
    <message>
        <source>Pixel row, 0 at the top</source>
        <translation>像素的行号，最上行为 0</translation>
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
        <source>Pixel</source>
        <translation>像素</translation>
    </message>
    <message>
        <source>Which of the pixel&apos;s %1 samples (each has its own random numbers)</source>
        <translation>该像素 %1 个样本中的第几个（每个样本使用各自的随机数）</translation>
    </message>
    <message>
        <source>Sample</source>
        <translation>样本</translation>
    </message>
    <message>
        <source>Trace this many samples of the pixel, from the sample above on, and draw them together: with a lens, the camera rays form the pixel&apos;s bundle</source>
        <translation>从上面选定的采样起，追踪这个像素的这么多个采样，并把它们画在一起：有透镜时，这些相机光线构成该像素的光线束</translation>
    </message>
    <message>
        <source>Samples drawn</source>
        <translation>同时绘制的采样数</translation>
    </message>
    <message>
        <source>Trace</source>
        <translation>追踪</translation>
    </message>
    <message>
        <source>Record this pixel sample&apos;s ray tree and show it in the view</source>
        <translation>记录这个像素样本的光线树，并在视图中显示</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Stop the trace that runs: the rays traced so far stay (a bushy tree can take long)</source>
        <translation>停止正在进行的追踪：已追踪的光线会保留（分支很多的光线树可能需要很长时间）</translation>
    </message>
    <message>
        <source>Rays across the image (the original program&apos;s 光线横向数量)</source>
        <translation>图像横向的光线数（对应原课程程序“光线横纵数量”中的横向数量）</translation>
    </message>
    <message>
        <source>Rays down the image (光线纵向数量)</source>
        <translation>图像纵向的光线数（对应原课程程序“光线横纵数量”中的纵向数量）</translation>
    </message>
    <message>
        <source>Simulate</source>
        <translation>仿真</translation>
    </message>
    <message>
        <source>Trace a grid of camera rays spread evenly over the image and draw all their ray trees, coloured by energy (1 x 1: the centre pixel)</source>
        <translation>追踪在图像上均匀分布的一组相机光线，并画出它们的全部光线树，按能量着色（1 × 1 时为中心像素）</translation>
    </message>
    <message>
        <source>across</source>
        <translation>横向</translation>
    </message>
    <message>
        <source>down</source>
        <translation>纵向</translation>
    </message>
    <message>
        <source>Rays</source>
        <translation>光线</translation>
    </message>
</context>
</TS>
